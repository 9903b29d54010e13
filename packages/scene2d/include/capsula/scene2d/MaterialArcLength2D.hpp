#pragma once
// Where a material point of a 2D membrane is: the map l(l0) from its reference arc length
// l0 to its current arc length l (eq A.38), splined through the marker nodes, which are
// material points; its slope is the stretch ratio omega = dl/dl0 (eq A.37).
//
// On a free cell only l - (L/L0) l0 is periodic, and that is what is splined (periodic
// ends); a tethered contour uses not-a-knot ends (no end data needed, exact for cubics).
// ElasticMembrane2D computes the stretch from it; TetherRegrid2D uses it to place new
// markers at chosen material points.
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/CubicSpline.hpp>

#include <vector>

namespace capsula::scene2d {

class MaterialArcLength2D {
public:
  /// l0 and l at the knots (N + 1 values each, from 0 to L0 and to L).
  MaterialArcLength2D(const std::vector<double>& referenceArcLengths, const std::vector<double>& currentArcLengths,
                      contour::Closure closure);

  /// The spline of l - meanStretch() l0 (the whole of l on a tethered contour).
  const contour::CubicSpline& spline() const { return spline_; }
  /// L / L0 on a free cell, 0 on a tethered one.
  double meanStretch() const { return meanStretch_; }

  /// l(l0). On a free cell l0 may lie outside [0, L0]; the result then lies outside [0, L]
  /// by the same number of periods.
  double currentArcLength(double referenceArcLength) const;
  /// omega = dl/dl0 at l0.
  double stretch(double referenceArcLength) const;
  /// The inverse, l0(l), for l in [0, L] (Newton's method from l L0 / L, safeguarded by
  /// bisection; l(l0) is strictly increasing wherever the membrane is not crushed, omega > 0).
  /// Throws if l(l0) - l does not change sign over the bracket.
  double referenceArcLength(double currentArcLength) const;

private:
  contour::CubicSpline spline_;
  double meanStretch_ = 0.0;
  double referenceLength_ = 0.0;
  double currentLength_ = 0.0;
  bool periodic_ = true;
};

} // namespace capsula::scene2d
