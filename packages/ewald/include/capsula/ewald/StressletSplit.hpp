#pragma once
// Hasimoto's split of the free-space stresslet T_ijk = -6 xh_i xh_j xh_k / r^5 (greens/
// FreeSpace3D.hpp: sigma_ik = T_ijk g_j / (8 pi) for a force g at x0, xh = x - x0), the stress of
// the split Stokeslet (EwaldSplit.hpp): T = T^R + T^F with
//   T^R_ijk = -P^R_j delta_ik + d_k G^R_ij + d_i G^R_kj
//           = c1(r) xh_i xh_j xh_k + c2(r) (delta_ij xh_k + delta_jk xh_i + delta_ik xh_j),
//   c1 = -6 erfc(xi r) / r^5 - (2 xi / sqrt(pi)) (6 / r^4 + 4 xi^2 / r^2) e^{-xi^2 r^2},
//   c2 = (4 xi^3 / sqrt(pi)) e^{-xi^2 r^2},
// where P^R_j = xh_j [2 erfc(xi r) / r^3 + (4 xi / sqrt(pi)) (1 / r^2 - xi^2) e^{-xi^2 r^2}] is the
// local part of the Stokeslet's pressure P_j = 2 xh_j / r^3, and
//   T^F^_ijk(k) = 8 pi i gamma^(k) [(delta_ik k_j + delta_ij k_k + delta_jk k_i) / k^2 - 2 k_i k_j k_k / k^4]
// (the transform of the pressure's smooth part is -8 pi i k_j gamma^(k) / k^2). T^R is fully
// symmetric like T, equals T minus an entire function that vanishes at r = 0 (T^F is odd), and
// decays like e^{-xi^2 r^2}.
#include <cmath>

namespace capsula::ewald {

/// c1(r) and c2(r) of T^R (header comment), r > 0.
inline void screenedStressletCoefficients(double r, double xi, double& c1, double& c2)
{
  constexpr double twoOverSqrtPi = 1.12837916709551257390;
  const double r2 = r * r;
  const double gauss = std::exp(-xi * xi * r2);
  c1 = -6.0 * std::erfc(xi * r) / (r2 * r2 * r) - twoOverSqrtPi * xi * (6.0 / (r2 * r2) + 4.0 * xi * xi / r2) * gauss;
  c2 = 2.0 * twoOverSqrtPi * xi * xi * xi * gauss;
}

/// The local part T^R_ijk(xh; xi) of the stresslet, stored T[i][j][k], xh != 0.
inline void screenedStresslet3D(const double xh[3], double xi, double T[3][3][3])
{
  const double r = std::sqrt(xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2]);
  double c1 = 0.0, c2 = 0.0;
  screenedStressletCoefficients(r, xi, c1, c2);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        T[i][j][k] = c1 * xh[i] * xh[j] * xh[k] +
                     c2 * ((i == j ? xh[k] : 0.0) + (j == k ? xh[i] : 0.0) + (i == k ? xh[j] : 0.0));
      }
    }
  }
}

/// The transform of the smooth part divided by i (it is purely imaginary): T^F^_ijk = i R[i][j][k].
inline void smoothStressletFourier3D(const double k[3], double xi, double R[3][3][3])
{
  constexpr double pi = 3.14159265358979323846;
  const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
  const double kappa = k2 / (4.0 * xi * xi);
  const double scale = 8.0 * pi * (1.0 + kappa) * std::exp(-kappa) / k2;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int l = 0; l < 3; ++l) {
        const double deltas = (i == l ? k[j] : 0.0) + (i == j ? k[l] : 0.0) + (j == l ? k[i] : 0.0);
        R[i][j][l] = scale * (deltas - 2.0 * k[i] * k[j] * k[l] / k2);
      }
    }
  }
}

} // namespace capsula::ewald
