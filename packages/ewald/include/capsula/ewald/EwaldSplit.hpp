#pragma once
// Hasimoto's (1959) Ewald split of the free-space Stokeslet G_ij = delta_ij / r + xh_i xh_j / r^3
// (the convention of greens/FreeSpace3D.hpp: u = G g / (8 pi mu), xh = x - x0, r = |xh|):
//   G = G^R(xh; xi) + G^F(xh; xi),
// with the Fourier transform (f^(k) = int f(x) e^{-i k.x} dx) of the smooth part
//   G^F^(k) = 8 pi (delta_ij k^2 - k_i k_j) / k^4 * (1 + k^2 / (4 xi^2)) e^{-k^2 / (4 xi^2)},
// that is the Stokeslet of the screening force density
//   gamma(r) = xi^3 pi^{-3/2} (5/2 - xi^2 r^2) e^{-xi^2 r^2},   gamma^(k) = (1 + k^2/(4 xi^2)) e^{-k^2/(4 xi^2)},
// and the local part in closed form (Lindbo & Tornberg 2011, eq 2.5 written out)
//   G^R_ij = [erfc(xi r) / r - 2 xi / sqrt(pi) e^{-xi^2 r^2}] delta_ij
//          + [erfc(xi r) / r^3 + 2 xi / (sqrt(pi) r^2) e^{-xi^2 r^2}] xh_i xh_j.
// G^R is the Stokeslet minus a smooth (entire) remainder, G - G^R = G^F with
// G^F(0) = 4 xi / sqrt(pi) delta_ij, so singular and near-singular quadrature written for the
// Stokeslet applies to G^R unchanged; G^R decays like e^{-xi^2 r^2}. Sources that are
// derivatives of the Stokeslet (doublets, dipoles, the stresslet) split the same way: their
// Fourier part multiplies G^F^ by the factors i k, their local part differentiates G^R.
#include <cmath>

namespace capsula::ewald {

/// Hasimoto's screening factor gamma^(k) = (1 + k^2 / (4 xi^2)) e^{-k^2 / (4 xi^2)}.
inline double hasimotoScreening(double k2, double xi)
{
  const double kappa = k2 / (4.0 * xi * xi);
  return (1.0 + kappa) * std::exp(-kappa);
}

/// Coefficients of G^R = a(r) delta + b(r) xh xh (header comment), r > 0.
inline void screenedStokesletCoefficients(double r, double xi, double& a, double& b)
{
  constexpr double invSqrtPi = 0.56418958354775628695; // 1 / sqrt(pi)
  const double erfcTerm = std::erfc(xi * r) / r;
  const double gaussTerm = 2.0 * xi * invSqrtPi * std::exp(-xi * xi * r * r);
  a = erfcTerm - gaussTerm;
  b = (erfcTerm + gaussTerm) / (r * r);
}

/// The local part G^R_ij(xh; xi) of the Stokeslet (header comment), xh = x - x0 != 0.
inline void screenedStokeslet3D(const double xh[3], double xi, double G[3][3])
{
  const double r = std::sqrt(xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2]);
  double a = 0.0, b = 0.0;
  screenedStokesletCoefficients(r, xi, a, b);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      G[i][j] = b * xh[i] * xh[j];
    }
    G[i][i] += a;
  }
}

/// The Fourier transform G^F^_ij(k; xi) of the smooth part (header comment), k != 0.
inline void smoothStokesletFourier3D(const double k[3], double xi, double Ghat[3][3])
{
  constexpr double pi = 3.14159265358979323846;
  const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
  const double scale = 8.0 * pi * hasimotoScreening(k2, xi) / (k2 * k2);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Ghat[i][j] = -scale * k[i] * k[j];
    }
    Ghat[i][i] += scale * k2;
  }
}

/// The value G^F(0) = 4 xi / sqrt(pi) delta_ij of the smooth part at the pole (a source's own
/// contribution to the Fourier sum, removed from a sum that excludes the pole).
inline double smoothStokesletAtPole(double xi)
{
  constexpr double twoOverSqrtPi = 1.12837916709551257390;
  return 2.0 * twoOverSqrtPi * xi;
}

} // namespace capsula::ewald
