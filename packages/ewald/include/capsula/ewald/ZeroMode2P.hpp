#pragma once
// The (k_x, k_z) = 0 mode of the Stokeslet in a layer periodic in x and z (periods L_x, L_z,
// area A = L_x L_z), unbounded in y. Averaged over x and z, a force g per cell at height y0 is a
// force sheet g / A; the 1D Stokes problem mu u'' = -(g / A) delta(y - y0) has the solution
//   u_parallel(y) = -g_parallel |y - y0| / (2 mu A) + const,   u_y = 0
// (the pressure p = -(g_y / (2 A)) sign(y - y0) carries the normal force). This package fixes the
// constant at zero: the x-z average of the periodic Stokeslet is, in the convention
// u = G g / (8 pi mu),
//   <G>_parallel(y - y0) = -4 pi |y - y0| / A,   <G>_yy = 0,   <G>_xy = <G>_yz = <G>_xz = 0,
// zero at the source's height. The flow of one force grows linearly in |y|; the flow of forces
// g_n at heights y_n with sum g_n = 0 tends to the constant +(4 pi / A) sign(y) sum g_n y_n (in
// G units) as |y| -> infinity, so force-free configurations have a bounded field.
//
// In the Ewald split the average of the local part, <G^R>, decays like e^{-xi^2 y^2}; the
// smooth part carries the rest, which is the 1D Stokeslet of the x-z averaged screening
// density gamma_1(y) = xi / sqrt(pi) (3/2 - xi^2 y^2) e^{-xi^2 y^2} (EwaldSplit.hpp):
//   <G^F>_parallel(y) = h(y) / A,   h(y) = -4 pi [y erf(xi y) + e^{-xi^2 y^2} / (2 sqrt(pi) xi)],
// with h'' = -8 pi gamma_1 and h(y) + 4 pi |y| -> 0 as |y| -> infinity (which fixes the
// constant above).
#include <cmath>

namespace capsula::ewald {

/// h(y) of the header comment: the zero mode of the smooth part times the cell area A.
inline double smoothZeroModeProfile(double y, double xi)
{
  constexpr double pi = 3.14159265358979323846;
  constexpr double invSqrtPi = 0.56418958354775628695;
  return -4.0 * pi * (y * std::erf(xi * y) + invSqrtPi * std::exp(-xi * xi * y * y) / (2.0 * xi));
}

/// -4 pi |y|: the zero mode of the whole periodic Stokeslet (parallel components) times A.
inline double zeroModeProfile(double y)
{
  constexpr double pi = 3.14159265358979323846;
  return -4.0 * pi * std::fabs(y);
}

/// The stresslet's zero mode (StressletReference2P.hpp) times A: the y-derivative of the
/// Stokeslet's, -4 pi sign(y) for the whole sum and, for the smooth part,
/// h'(y) = -4 pi [erf(xi y) + xi y e^{-xi^2 y^2} / sqrt(pi)].
inline double smoothStressletZeroModeProfile(double y, double xi)
{
  constexpr double pi = 3.14159265358979323846;
  constexpr double invSqrtPi = 0.56418958354775628695;
  return -4.0 * pi * (std::erf(xi * y) + invSqrtPi * xi * y * std::exp(-xi * xi * y * y));
}

} // namespace capsula::ewald
