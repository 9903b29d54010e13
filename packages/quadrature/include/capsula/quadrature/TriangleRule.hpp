#pragma once
// Gauss rules on the reference triangle T = {(xi, eta): xi, eta >= 0, xi + eta <= 1}
// (thesis eq 3.39, the N_Q-point rules of Pozrikidis 2002 / Dunavant 1985).
//
// Convention: the weights sum to 1/2, the area of T, so int_T f = sum_k w_k f(xi_k, eta_k).
// (Eq 3.39 writes the same rule with weights summing to 1 and an explicit factor 1/2.)
#include <vector>

namespace capsula::quadrature {

struct TriangleRule {
  int degree = 0;             ///< exact for every polynomial of total degree <= degree
  std::vector<double> xi;     ///< first parametric coordinate of each point
  std::vector<double> eta;    ///< second parametric coordinate of each point
  std::vector<double> weight; ///< sums to 1/2

  int size() const { return static_cast<int>(weight.size()); }
};

/// The fully symmetric rule with `numPoints` points (N_Q in the thesis):
///   N_Q  1  3  4  6  7  9  12  13  16  19
///   deg  1  2  3  4  5  5   6   7   8   9
/// The 4- and 13-point rules have a negative centroid weight. Throws core::InputError
/// naming numPoints and listing the supported counts otherwise.
const TriangleRule& triangleRule(int numPoints);

/// The point counts triangleRule accepts, ascending.
std::vector<int> supportedTriangleRules();

/// A rule of any degree, for reference values: the collapsed (Duffy) product of two
/// n-point Gauss-Legendre rules, xi = u, eta = (1 - u) v with Jacobian (1 - u); it has
/// n^2 points and degree 2n - 2 (the Jacobian uses up one degree in u).
/// Throws core::InputError unless nPerDirection >= 1.
TriangleRule collapsedTriangleRule(int nPerDirection);

} // namespace capsula::quadrature
