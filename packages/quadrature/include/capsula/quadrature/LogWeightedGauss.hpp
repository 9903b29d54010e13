#pragma once
// Gauss rules for a logarithmic end-point singularity (thesis eq A.47, ERRATA fix of
// A.46-A.47): the 2D single layer's ln r singularity on the element holding the pole.
#include <capsula/quadrature/Rule1D.hpp>

namespace capsula::quadrature {

/// Largest order logWeightedGauss accepts (the modified moments stay representable).
inline constexpr int maxLogWeightedGaussOrder = 100;

/// The n-point Gauss rule for the weight -ln(x) on [0, 1]:
///   int_0^1 -ln(x) f(x) dx ~= sum_k w_k f(x_k),   exact for polynomials of degree 2n-1.
/// Computed from modified moments against shifted Legendre polynomials (Gautschi's
/// modified Chebyshev algorithm, well conditioned for this weight), Golub-Welsch for the
/// nodes, one Newton polish and Christoffel numbers for the weights.
/// Throws core::InputError unless 1 <= n <= maxLogWeightedGaussOrder.
Rule1D logWeightedGauss(int n);

} // namespace capsula::quadrature
