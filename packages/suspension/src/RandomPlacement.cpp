#include "capsula/suspension/RandomPlacement.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/scene/CellPlacement.hpp>
#include <capsula/scene/SurfaceGap.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace capsula::suspension {

namespace {

using mesh::Mat3;
using mesh::Vec3;

// Uniform doubles in [0, 1) from the 53 high bits of the fixed mt19937_64 sequence (the
// standard's distributions may differ between libraries; this does not).
class UnitRandom {
public:
  explicit UnitRandom(unsigned long long seed) : engine_(seed) {}
  double operator()() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

private:
  std::mt19937_64 engine_;
};

// A uniformly random rotation as an axis and an angle (Shoemake's unit quaternion).
void randomRotation(UnitRandom& random, Vec3& axis, double& angle)
{
  const double u1 = random(), u2 = random(), u3 = random();
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double w = b * std::cos(2.0 * M_PI * u3);
  const Vec3 v(a * std::sin(2.0 * M_PI * u2), a * std::cos(2.0 * M_PI * u2), b * std::sin(2.0 * M_PI * u3));
  angle = 2.0 * std::atan2(v.norm(), w);
  axis = v.norm() > 0.0 ? Vec3(v / v.norm()) : Vec3(Vec3::UnitZ());
}

struct Extent {
  Vec3 lower, upper;
};

Extent extentOf(const std::vector<double>& positions)
{
  Extent e{Vec3::Constant(HUGE_VAL), Vec3::Constant(-HUGE_VAL)};
  for (std::size_t i = 0; i < positions.size(); i += 3) {
    const Vec3 p(positions[i], positions[i + 1], positions[i + 2]);
    e.lower = e.lower.cwiseMin(p);
    e.upper = e.upper.cwiseMax(p);
  }
  return e;
}

double boundingRadius(const mesh::SurfaceMesh& shape)
{
  double r = 0.0;
  for (int i = 0; i < shape.numNodes(); ++i) {
    r = std::max(r, shape.position(i).norm());
  }
  return r;
}

// Whether the candidate at `centre` keeps `gap` from the placed cell and its images.
bool clearOf(const mesh::SurfaceMesh& candidate, const Vec3& centre, double radius, const PlacedCell& placed,
             double placedRadius, const domain::Domain& domain, double gap)
{
  for (int i = -1; i <= 1; ++i) {
    for (int k = -1; k <= 1; ++k) {
      const Vec3 shift(i * domain.period(domain::flowAxis), 0.0, k * domain.period(domain::vorticityAxis));
      if ((placed.centre + shift - centre).norm() > radius + placedRadius + gap) {
        continue;
      }
      std::vector<double> moved = placed.surface.positions();
      for (std::size_t n = 0; n < moved.size(); ++n) {
        moved[n] += shift[static_cast<int>(n % 3)];
      }
      mesh::SurfaceMesh image = placed.surface;
      image.setPositions(moved);
      if (scene::surfacesOverlap(candidate, image) || scene::minimumSurfaceGap(candidate, image).distance <= gap) {
        return false;
      }
    }
  }
  return true;
}

} // namespace

std::vector<PlacedCell> placeCells(const std::vector<CellType>& types, const domain::Domain& domain,
                                   const PlacementSettings& settings)
{
  core::require<core::InputError>(domain.hasUpperWall() && domain.isPeriodic(domain::flowAxis) &&
                                      domain.isPeriodic(domain::vorticityAxis),
                                  "A suspension is placed in a channel periodic along x and z ('Wall/Channel "
                                  "height', 'Domain/Periodic length x' and 'z' all > 0), not in ",
                                  domain.describe(), ".");
  // Largest first: the big cells find room before the small ones fill the gaps.
  std::vector<int> order(types.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> radii;
  for (const auto& type : types) {
    radii.push_back(boundingRadius(type.shape));
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return radii[a] > radii[b]; });

  const double lx = domain.period(domain::flowAxis), lz = domain.period(domain::vorticityAxis);
  const double height = domain.channelHeight();
  UnitRandom random(settings.seed);
  std::vector<PlacedCell> placed;
  std::vector<double> placedRadii;
  for (int t : order) {
    const CellType& type = types[static_cast<std::size_t>(t)];
    for (int c = 0; c < type.count; ++c) {
      bool done = false;
      for (int attempt = 0; attempt < settings.attempts && !done; ++attempt) {
        PlacedCell cell{t, Vec3::Zero(), Vec3::UnitZ(), 0.0, type.shape};
        double angle = 0.0;
        randomRotation(random, cell.axis, angle);
        cell.angleDegrees = angle * 180.0 / M_PI;
        const Mat3 rotation = mesh::rotationAboutAxis(cell.axis, angle);
        std::vector<double> body = type.shape.positions();
        for (std::size_t n = 0; n < body.size(); n += 3) {
          const Vec3 x = rotation * Vec3(body[n], body[n + 1], body[n + 2]);
          body[n] = x[0], body[n + 1] = x[1], body[n + 2] = x[2];
        }
        const Extent extent = extentOf(body);
        const double yLow = settings.minimumWallGap - extent.lower[1];
        const double yHigh = height - settings.minimumWallGap - extent.upper[1];
        const double x = random() * lx, yUnit = random(), z = random() * lz;
        const bool fitsBox = extent.upper[0] - extent.lower[0] + settings.minimumCellGap < lx &&
                             extent.upper[2] - extent.lower[2] + settings.minimumCellGap < lz;
        if (!(yHigh > yLow) || !fitsBox) {
          continue;
        }
        cell.centre = Vec3(x, yLow + yUnit * (yHigh - yLow), z);
        for (std::size_t n = 0; n < body.size(); ++n) {
          body[n] += cell.centre[static_cast<int>(n % 3)];
        }
        cell.surface.setPositions(body);
        done = std::all_of(placed.begin(), placed.end(), [&](const PlacedCell& other) {
          return clearOf(cell.surface, cell.centre, radii[static_cast<std::size_t>(t)], other,
                         placedRadii[static_cast<std::size_t>(&other - placed.data())], domain,
                         settings.minimumCellGap);
        });
        if (done) {
          placed.push_back(std::move(cell));
          placedRadii.push_back(radii[static_cast<std::size_t>(t)]);
        }
      }
      if (!done) {
        double volume = 0.0;
        for (const auto& p : placed) {
          volume += mesh::enclosedVolume(p.surface);
        }
        throw core::InputError(
            core::message("The suspension jams: cell ", c + 1, " of the ", type.count, " of type '", type.name,
                          "' found no place in ", settings.attempts, " random tries, with ", placed.size(),
                          " cells placed (volume fraction ", volume / (lx * height * lz),
                          "). Lower the hematocrit or the counts, or enlarge the box ('Domain/Periodic length x', 'z', "
                          "'Wall/Channel height')."));
      }
    }
  }
  return placed;
}

int cellsForHematocrit(double hematocrit, double cellVolume, const domain::Domain& domain)
{
  const double box = domain.period(domain::flowAxis) * domain.channelHeight() * domain.period(domain::vorticityAxis);
  core::require<core::InputError>(box > 0.0 && cellVolume > 0.0 && hematocrit > 0.0,
                                  "'Suspension/Hematocrit' = ", hematocrit,
                                  " needs a finite box (a channel periodic along x and z) and cells of volume > 0.");
  const int count = static_cast<int>(std::lround(hematocrit * box / cellVolume));
  const double reached = count * cellVolume / box;
  core::require<core::InputError>(count >= 1 && std::abs(reached - hematocrit) <= 0.01 * hematocrit,
                                  "'Suspension/Hematocrit' = ", hematocrit,
                                  " cannot be met within 1% in a box of volume ", box, ": one cell of volume ",
                                  cellVolume, " is ", cellVolume / box, " of it, and ", count, " cells give ", reached,
                                  ". Enlarge the box ('Domain/Periodic length x', 'z') or adjust the hematocrit.");
  return count;
}

} // namespace capsula::suspension
