#include "capsula/scene2d/BendingState2D.hpp"

#include "capsula/scene2d/BendingLoad2D.hpp"

#include <utility>

namespace capsula::scene2d {

BendingState2D::BendingState2D(double modulus, contour::CubicSpline misfit,
                               std::optional<contour::CubicSpline> reference)
    : modulus_(modulus), misfitSpline_(std::move(misfit)), referenceSpline_(std::move(reference))
{}

Eigen::Vector2d BendingState2D::loadAt(const contour::ContourPoint& point, int segment, double offset) const
{
  const contour::CubicPiece& q = misfitSpline_.piece(segment);
  double reference = 0.0, referenceSlope = 0.0;
  if (referenceSpline_) {
    const contour::CubicPiece& r = referenceSpline_->piece(segment);
    reference = r.value(offset);
    referenceSlope = r.derivative(offset);
  }
  return bendingLoad2D(modulus_, q.value(offset), q.secondDerivative(offset), reference, referenceSlope, point);
}

} // namespace capsula::scene2d
