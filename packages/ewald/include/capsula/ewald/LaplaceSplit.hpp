#pragma once
// Ewald's Gaussian split of the Laplace kernel 1/r and of its first two derivatives, the
// pieces of the wall's image system (WallStokeslet2P.hpp) that are not Stokeslets:
//   1/r = erfc(xi r)/r + erf(xi r)/r,   Fourier transform of the smooth part 4 pi e^{-k^2/(4 xi^2)} / k^2.
// The local part phi^R = erfc(xi r)/r has, with xh = x - x0 and r = |xh|,
//   d_i phi^R      = f1(r) xh_i,
//   d_i d_j phi^R  = f1(r) delta_ij + f2(r) xh_i xh_j,
//   f1 = -erfc(xi r)/r^3 - 2 xi e^{-xi^2 r^2} / (sqrt(pi) r^2),
//   f2 = 3 erfc(xi r)/r^5 + 6 xi e^{-xi^2 r^2} / (sqrt(pi) r^4) + 4 xi^3 e^{-xi^2 r^2} / (sqrt(pi) r^2)
//   d_i d_j d_k phi^R = f2(r) (delta_ij xh_k + delta_ik xh_j + delta_jk xh_i) + f3(r) xh_i xh_j xh_k,
//   f3 = -15 erfc(xi r)/r^7 - (2 xi e^{-xi^2 r^2} / (sqrt(pi) r^2)) (15/r^4 + 10 xi^2/r^2 + 4 xi^4)
// (f1 = phi'/r, f2 = f1'/r, f3 = f2'/r, derived symbolically; xi -> 0 gives the unscreened
// -1/r^3, 3/r^5 and -15/r^7). Per Fourier mode (kx, kz) != 0 of a layer periodic in x and z, the smooth
// part's ky integral is (1/2pi) int 4 pi e^{-k^2/(4 xi^2)} / k^2 e^{i ky y} dky = pi P(y) / a with
// a = |(kx, kz)| and P, D, g of Ewald2PReference.hpp; its y-derivatives follow from
// P' = a D and D' = a P - 4 xi g / sqrt(pi).
#include <cmath>

namespace capsula::ewald {

/// f1(r) and f2(r) of the header comment, r > 0.
inline void screenedLaplaceCoefficients(double r, double xi, double& f1, double& f2)
{
  constexpr double invSqrtPi = 0.56418958354775628695; // 1 / sqrt(pi)
  const double r2 = r * r;
  const double erfcTerm = std::erfc(xi * r) / (r2 * r);
  const double gauss = 2.0 * xi * invSqrtPi * std::exp(-xi * xi * r2) / r2;
  f1 = -erfcTerm - gauss;
  f2 = 3.0 * (erfcTerm + gauss) / r2 + 2.0 * xi * xi * gauss;
}

/// f3(r) of the header comment, r > 0.
inline double screenedLaplaceThirdCoefficient(double r, double xi)
{
  constexpr double invSqrtPi = 0.56418958354775628695;
  const double r2 = r * r;
  const double erfcTerm = std::erfc(xi * r) / (r2 * r);
  const double gauss = 2.0 * xi * invSqrtPi * std::exp(-xi * xi * r2) / r2;
  const double xi2 = xi * xi;
  return -15.0 * erfcTerm / (r2 * r2) - gauss * (15.0 / (r2 * r2) + 10.0 * xi2 / r2 + 4.0 * xi2 * xi2);
}

/// The smooth part's multiplier 4 pi e^{-(1 - eta) k^2/(4 xi^2)} / k^2 on a spectral Ewald grid
/// whose Gaussian windows took eta of the screening (SpectralEwald2P.hpp); each derivative
/// d_a multiplies it by i k_a.
inline double laplaceSmoothMultiplier(const double k[3], double xi, double eta)
{
  constexpr double multiplierPi = 3.14159265358979323846;
  const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
  return 4.0 * multiplierPi * std::exp(-(1.0 - eta) * k2 / (4.0 * xi * xi)) / k2;
}

/// xi' = xi / sqrt(1 - eta): the screening of the zero mode's 1D profile once the windows are
/// taken out.
inline double windowedXi(double xi, double eta)
{
  return xi / std::sqrt(1.0 - eta);
}

/// The local part d_i d_j d_k phi^R at xh != 0.
inline void screenedLaplaceThirdDerivatives3D(const double xh[3], double xi, double third[3][3][3])
{
  const double r = std::sqrt(xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2]);
  double f1 = 0.0, f2 = 0.0;
  screenedLaplaceCoefficients(r, xi, f1, f2);
  const double f3 = screenedLaplaceThirdCoefficient(r, xi);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        const double deltas = (i == j ? xh[k] : 0.0) + (i == k ? xh[j] : 0.0) + (j == k ? xh[i] : 0.0);
        third[i][j][k] = f2 * deltas + f3 * xh[i] * xh[j] * xh[k];
      }
    }
  }
}

/// The local parts d_i phi^R (gradient) and d_i d_j phi^R (hessian) at xh != 0.
inline void screenedLaplaceDerivatives3D(const double xh[3], double xi, double gradient[3], double hessian[3][3])
{
  const double r = std::sqrt(xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2]);
  double f1 = 0.0, f2 = 0.0;
  screenedLaplaceCoefficients(r, xi, f1, f2);
  for (int i = 0; i < 3; ++i) {
    gradient[i] = f1 * xh[i];
    for (int j = 0; j < 3; ++j) {
      hessian[i][j] = f2 * xh[i] * xh[j];
    }
    hessian[i][i] += f1;
  }
}

} // namespace capsula::ewald
