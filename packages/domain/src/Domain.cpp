#include "capsula/domain/Domain.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>
#include <limits>
#include <sstream>

namespace capsula::domain {

namespace {

void requireLength(double value, const char* what)
{
  core::require<core::InputError>(std::isfinite(value) && value >= 0.0, "The domain's ", what,
                                  " must be finite and >= 0 (0: none), not ", value, ".");
}

} // namespace

Domain::Domain(const DomainShape& shape) : shape_(shape)
{
  requireLength(shape.channelHeight, "channel height");
  requireLength(shape.periodX, "period along x");
  requireLength(shape.periodZ, "period along z");
  core::require<core::InputError>(shape.channelHeight == 0.0 || shape.lowerWall, "A channel (height ",
                                  shape.channelHeight,
                                  ") needs its lower wall y = 0: the upper wall alone is not a domain.");
  periods_ = {shape.periodX, 0.0, shape.periodZ};
  if (shape.lowerWall) {
    walls_.push_back(Wall{0.0, 1, "lower wall"});
  }
  if (shape.channelHeight > 0.0) {
    walls_.push_back(Wall{shape.channelHeight, -1, "upper wall"});
  }
}

Domain Domain::unbounded()
{
  return Domain(DomainShape{false, 0.0, 0.0, 0.0});
}

Domain Domain::aboveWall()
{
  return Domain(DomainShape{true, 0.0, 0.0, 0.0});
}

Domain Domain::channel(double height)
{
  return Domain(DomainShape{true, height, 0.0, 0.0});
}

void Domain::nearestImage(double d[3]) const
{
  for (int axis = 0; axis < 3; ++axis) {
    const double length = periods_[static_cast<std::size_t>(axis)];
    if (length > 0.0) {
      // round() brings d into [-L/2, L/2]; ties (exactly L/2) keep either image.
      d[axis] -= length * std::round(d[axis] / length);
    }
  }
}

std::array<double, 3> Domain::separation(const double a[3], const double b[3]) const
{
  std::array<double, 3> d{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  nearestImage(d.data());
  return d;
}

std::array<double, 3> Domain::foldingShift(const double x[3]) const
{
  std::array<double, 3> shift{};
  for (int axis = 0; axis < 3; ++axis) {
    const double length = periods_[static_cast<std::size_t>(axis)];
    if (length > 0.0) {
      shift[static_cast<std::size_t>(axis)] = -length * std::floor(x[axis] / length);
    }
  }
  return shift;
}

double Domain::distanceToNearestWall(const double x[3], int* nearest) const
{
  double best = std::numeric_limits<double>::infinity();
  int index = -1;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const double d = walls_[w].distance(x[wallNormalAxis]);
    if (index < 0 || d < best || std::isnan(d)) {
      best = d;
      index = static_cast<int>(w);
    }
  }
  if (nearest != nullptr) {
    *nearest = index;
  }
  return best;
}

bool Domain::inFluid(const double x[3]) const
{
  return firstPointOutsideFluid(x, 1, 3) < 0;
}

int Domain::firstPointOutsideFluid(const double* points, int numPoints, int dimension) const
{
  core::require<core::Error>(dimension == 2 || dimension == 3, "points of dimension ", dimension,
                             ": a domain holds 2D or 3D points");
  for (int i = 0; i < numPoints; ++i) {
    const double y = points[static_cast<std::size_t>(dimension) * i + wallNormalAxis];
    for (const Wall& wall : walls_) {
      if (!(wall.distance(y) > 0.0)) { // NaN fails too
        return i;
      }
    }
  }
  return -1;
}

std::string Domain::nearestWallName(double y) const
{
  const double x[3] = {0.0, y, 0.0};
  int nearest = -1;
  distanceToNearestWall(x, &nearest);
  return nearest >= 0 && walls_[static_cast<std::size_t>(nearest)].fluidSide < 0 ? "the upper wall" : "the wall";
}

std::string Domain::describe() const
{
  std::ostringstream out;
  if (hasUpperWall()) {
    out << "a channel 0 < y < " << shape_.channelHeight;
  } else if (hasLowerWall()) {
    out << "the fluid above the wall y = 0";
  } else {
    out << "unbounded fluid";
  }
  if (isPeriodic(flowAxis) && isPeriodic(vorticityAxis)) {
    out << ", periodic along x and z (L_x = " << period(flowAxis) << ", L_z = " << period(vorticityAxis) << ")";
  } else if (isPeriodic(flowAxis)) {
    out << ", periodic along x (L_x = " << period(flowAxis) << ")";
  } else if (isPeriodic(vorticityAxis)) {
    out << ", periodic along z (L_z = " << period(vorticityAxis) << ")";
  }
  return out.str();
}

} // namespace capsula::domain
