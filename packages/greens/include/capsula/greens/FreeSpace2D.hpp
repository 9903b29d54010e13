#pragma once
// Stokes flow of a point force in unbounded 2D fluid (thesis eqs A.6-A.9; Pozrikidis 1992).
//
// Same conventions as FreeSpace3D.hpp (x field point, x0 pole, xh = x - x0, j the force
// index, T[i][j][k]) with the 2D normalisation
//   u_i(x) = G_ij g_j / (4 pi mu),   sigma_ik(x) = T_ijk g_j / (4 pi),   p(x) = P_j g_j / (4 pi).
#include <cmath>

namespace capsula::greens {

/// Stokeslet G_ij = -delta_ij ln r + xh_i xh_j / r^2 (eq A.8), xh = x - x0 != 0.
inline void stokesletFreeSpace2D(const double xh[2], double G[2][2])
{
  const double r2 = xh[0] * xh[0] + xh[1] * xh[1];
  const double invR2 = 1.0 / r2;
  const double minusLogR = -0.5 * std::log(r2);
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      G[i][j] = xh[i] * xh[j] * invR2;
    }
    G[i][i] += minusLogR;
  }
}

/// Stresslet T_ijk = -4 xh_i xh_j xh_k / r^4 (eq A.9), xh = x - x0 != 0.
inline void stressletFreeSpace2D(const double xh[2], double T[2][2][2])
{
  const double r2 = xh[0] * xh[0] + xh[1] * xh[1];
  const double scale = -4.0 / (r2 * r2);
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      for (int k = 0; k < 2; ++k) {
        T[i][j][k] = scale * xh[i] * xh[j] * xh[k];
      }
    }
  }
}

/// Pressure vector P_j = 2 xh_j / r^2 of the Stokeslet, so that
/// T_ijk = -P_j delta_ik + dG_ij/dx_k + dG_kj/dx_i.
inline void pressureFreeSpace2D(const double xh[2], double P[2])
{
  const double scale = 2.0 / (xh[0] * xh[0] + xh[1] * xh[1]);
  P[0] = scale * xh[0];
  P[1] = scale * xh[1];
}

/// Kernel policy for operators templated on the Green's function.
struct FreeSpace2D {
  static constexpr int dimension = 2;
  static constexpr const char* name = "free-space 2D";

  /// G_ij(x, x0): velocity at field point x of a unit force along j at pole x0.
  static void stokeslet(const double x[2], const double x0[2], double G[2][2])
  {
    const double xh[2] = {x[0] - x0[0], x[1] - x0[1]};
    stokesletFreeSpace2D(xh, G);
  }
  /// T_ijk(x, x0): stress sigma_ik at field point x of a unit force along j at pole x0.
  static void stresslet(const double x[2], const double x0[2], double T[2][2][2])
  {
    const double xh[2] = {x[0] - x0[0], x[1] - x0[1]};
    stressletFreeSpace2D(xh, T);
  }
  /// P_j(x, x0): pressure at field point x of a unit force along j at pole x0.
  static void pressure(const double x[2], const double x0[2], double P[2])
  {
    const double xh[2] = {x[0] - x0[0], x[1] - x0[1]};
    pressureFreeSpace2D(xh, P);
  }
};

} // namespace capsula::greens
