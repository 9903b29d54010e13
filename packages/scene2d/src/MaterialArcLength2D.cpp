#include "capsula/scene2d/MaterialArcLength2D.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>
#include <cstddef>

namespace capsula::scene2d {

namespace {

contour::CubicSpline materialSpline(const std::vector<double>& l0, const std::vector<double>& l,
                                    contour::Closure closure, double meanStretch)
{
  core::require<core::InputError>(l0.size() == l.size() && l0.size() >= 4, "MaterialArcLength2D: ", l0.size(),
                                  " reference and ", l.size(),
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
    : spline_(materialSpline(
          referenceArcLengths, currentArcLengths, closure,
          closure == contour::Closure::Periodic ? currentArcLengths.back() / referenceArcLengths.back() : 0.0)),
      meanStretch_(closure == contour::Closure::Periodic ? currentArcLengths.back() / referenceArcLengths.back() : 0.0),
      referenceLength_(referenceArcLengths.back()),
      currentLength_(currentArcLengths.back()),
      periodic_(closure == contour::Closure::Periodic)
{}

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
  // Newton's method safeguarded by bisection: l(l0) - l changes sign on [lo, hi] and a
  // Newton step that leaves the bracket is replaced by its midpoint, so round-off cannot make
  // it cycle. The bracket: [0, L0] on a tethered contour; on a free cell the root lies within
  // L0 of l L0 / L, because l - (L / L0) l0 is periodic and between -L and L.
  const auto residual = [&](double l0) { return this->currentArcLength(l0) - currentArcLength; };
  const double guess = currentArcLength * referenceLength_ / currentLength_;
  double lo = periodic_ ? guess - referenceLength_ : 0.0;
  double hi = periodic_ ? guess + referenceLength_ : referenceLength_;
  core::require(residual(lo) <= 0.0 && residual(hi) >= 0.0,
                "MaterialArcLength2D: l(l0) does not bracket l = ", currentArcLength,
                ": the membrane is crushed (stretch <= 0) somewhere");
  double l0 = guess; // the root for a uniform stretch
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double r = residual(l0);
    (r < 0.0 ? lo : hi) = l0;
    const double omega = stretch(l0);
    double next = omega > 0.0 ? l0 - r / omega : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
    }
    if (std::abs(next - l0) <= 1e-14 * referenceLength_ || hi - lo <= 1e-14 * referenceLength_) {
      return next;
    }
    l0 = next;
  }
  core::require(false, "MaterialArcLength2D: no l0 found for l = ", currentArcLength);
  return l0;
}

} // namespace capsula::scene2d
