#include "capsula/scene2d/MembraneState2D.hpp"

#include "capsula/scene2d/MembraneLoad2D.hpp"

#include <cstddef>
#include <utility>

namespace capsula::scene2d {

MembraneState2D::MembraneState2D(contour::Contour current, contour::CubicSpline tensionSpline)
    : contour_(std::move(current)), tensionSpline_(std::move(tensionSpline))
{}

namespace {

/// Offset l - l_k of the point (k, t) into piece k of a spline whose knots are the
/// contour's knot arc lengths.
double arcOffset(const contour::Contour& c, int segment, double t)
{
  return c.arcLengthAt(segment, t) - c.knotArcLengths()[static_cast<std::size_t>(segment)];
}

} // namespace

double MembraneState2D::tensionAt(int segment, double t) const
{
  return tensionSpline_.piece(segment).value(arcOffset(contour_, segment, t));
}

double MembraneState2D::tensionSlopeAt(int segment, double t) const
{
  return tensionSpline_.piece(segment).derivative(arcOffset(contour_, segment, t));
}

Eigen::Vector2d MembraneState2D::loadAt(int segment, double t) const
{
  return loadAt(contour_.pointAt(segment, t), segment, t);
}

Eigen::Vector2d MembraneState2D::loadAt(const contour::ContourPoint& point, int segment, double t) const
{
  const contour::CubicPiece& piece = tensionSpline_.piece(segment);
  const double offset = arcOffset(contour_, segment, t);
  const Eigen::Vector2d tension = membraneLoad2D(piece.value(offset), piece.derivative(offset), point);
  return bending_ ? Eigen::Vector2d(tension + bending_->loadAt(point, segment, offset)) : tension;
}

Eigen::Vector2d MembraneState2D::netForce(int points) const
{
  return contour_.integrate([this](const contour::ContourPoint& p, int k, double t) { return loadAt(p, k, t); },
                            points);
}

double MembraneState2D::netTorque(int points, const Eigen::Vector2d& about) const
{
  return contour_.integrate(
      [this, &about](const contour::ContourPoint& p, int k, double t) {
        const Eigen::Vector2d r = p.position - about;
        const Eigen::Vector2d f = loadAt(p, k, t);
        return r.x() * f.y() - r.y() * f.x();
      },
      points);
}

} // namespace capsula::scene2d
