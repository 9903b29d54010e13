#include "capsula/elasticity/MaterialArcLength2D.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>
#include <cstddef>

namespace capsula::elasticity {

namespace {

contour::CubicSpline materialSpline(const std::vector<double>& l0, const std::vector<double>& l,
                                    contour::Closure closure, double meanStretch)
{
  core::require<core::InputError>(l0.size() == l.size() && l0.size() >= 4,
                                  "MaterialArcLength2D: ", l0.size(), " reference and ", l.size(),
                                  " current arc lengths; they must match and hold at least 4 knots");
  if (closure == contour::Closure::Periodic) {
    const std::size_t nodes = l0.size() - 1;
    std::vector<double> periodicPart(nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
      periodicPart[i] = l[i] - meanStretch * l0[i];
    }
    return contour::CubicSpline::periodic(l0, periodicPart);
  }
  return contour::CubicSpline::notAKnot(l0, l);
}

} // namespace

MaterialArcLength2D::MaterialArcLength2D(const std::vector<double>& referenceArcLengths,
                                         const std::vector<double>& currentArcLengths, contour::Closure closure)
  : spline_(materialSpline(referenceArcLengths, currentArcLengths, closure,
                           closure == contour::Closure::Periodic
                               ? currentArcLengths.back() / referenceArcLengths.back()
                               : 0.0)),
    meanStretch_(closure == contour::Closure::Periodic ? currentArcLengths.back() / referenceArcLengths.back() : 0.0),
    referenceLength_(referenceArcLengths.back()),
    currentLength_(currentArcLengths.back())
{
}

double MaterialArcLength2D::currentArcLength(double referenceArcLength) const
{
  return meanStretch_ * referenceArcLength + spline_.value(referenceArcLength);
}

double MaterialArcLength2D::stretch(double referenceArcLength) const
{
  return meanStretch_ + spline_.derivative(referenceArcLength);
}

double MaterialArcLength2D::referenceArcLength(double currentArcLength) const
{
  double l0 = currentArcLength * referenceLength_ / currentLength_;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double omega = stretch(l0);
    core::require(omega > 0.0, "MaterialArcLength2D: the stretch is ", omega, " at l0 = ", l0,
                  ": the membrane is crushed there and l(l0) cannot be inverted");
    const double step = (this->currentArcLength(l0) - currentArcLength) / omega;
    l0 -= step;
    if (std::abs(step) <= 1e-14 * referenceLength_) {
      return l0;
    }
  }
  core::require(false, "MaterialArcLength2D: Newton's method did not find l0 for l = ", currentArcLength);
  return l0;
}

} // namespace capsula::elasticity
