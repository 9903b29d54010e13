#pragma once
// Gauss-Legendre quadrature on an interval (thesis eqs 3.42-3.43, A.40).
#include <capsula/quadrature/Rule1D.hpp>

namespace capsula::quadrature {

/// The n-point Gauss-Legendre rule on [a, b]: int_a^b f(x) dx ~= sum_k w_k f(x_k),
/// exact for polynomials of degree 2n-1. Nodes are the zeros of the Legendre polynomial
/// P_n found by Newton's method to machine precision; the rule is exactly symmetric.
/// Throws core::InputError unless n >= 1.
Rule1D gaussLegendre(int n, double a = 0.0, double b = 1.0);

} // namespace capsula::quadrature
