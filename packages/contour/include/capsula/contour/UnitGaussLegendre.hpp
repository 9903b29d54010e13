#pragma once
// Gauss-Legendre rule on the unit interval, for integrals along spline segments
// (thesis eq A.40, mapped to t in [0, 1]).
#include <vector>

namespace capsula::contour {

/// n-point Gauss-Legendre rule on [0, 1]: exact for polynomials of degree 2n - 1.
struct UnitRule {
  std::vector<double> points;
  std::vector<double> weights; ///< sum to 1
};

/// Nodes by Newton iteration on the Legendre polynomial P_n (to round-off), n >= 1.
UnitRule unitGaussLegendre(int n);

} // namespace capsula::contour
