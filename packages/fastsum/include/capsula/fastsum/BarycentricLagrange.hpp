#pragma once
// Lagrange interpolation at Chebyshev points of the second kind in barycentric form
// (Berrut & Trefethen 2004, eqs 4.2 and 5.4; the treecode's interpolant, Wang, Tlupova &
// Krasny 2020, eqs 9-12).
//
// On [a, b] the n + 1 points are s_k = (a + b)/2 + (b - a)/2 cos(pi k / n) and the basis
//   L_k(x) = (w_k / (x - s_k)) / sum_l (w_l / (x - s_l)),   w_k = (-1)^k, halved at k = 0, n,
// which is stable for any x and costs O(n) for all k. The weights do not depend on the
// interval (a common factor cancels). At x = s_k the formula is 0/0: L is then the unit
// vector e_k. Chebyshev points keep the Lebesgue constant O(log n), so the interpolation
// error falls geometrically with n for a kernel smooth on a neighbourhood of the interval.
namespace capsula::fastsum {

/// The largest interpolation degree supported (the basis values live on the stack).
inline constexpr int maxInterpolationDegree = 16;

/// s[k], k = 0..degree: the Chebyshev points of the second kind on [a, b] (a <= b).
void chebyshevPoints(int degree, double a, double b, double* s);

/// values[k] = L_k(x), k = 0..degree, for the points s of chebyshevPoints(degree, ...).
void lagrangeBasis(int degree, const double* s, double x, double* values);

} // namespace capsula::fastsum
