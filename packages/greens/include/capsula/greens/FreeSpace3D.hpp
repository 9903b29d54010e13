#pragma once
// Stokes flow of a point force in unbounded 3D fluid (thesis eqs 3.9-3.12; Pozrikidis 1992).
//
// Argument order everywhere in this package: x is the field point (where velocity and
// stress are evaluated; the integration point of the boundary integrals), x0 is the pole
// (where the point force acts), xh = x - x0 and r = |xh|. For a force g at x0:
//   u_i(x) = G_ij g_j / (8 pi mu),   sigma_ik(x) = T_ijk g_j / (8 pi),   p(x) = P_j g_j / (8 pi),
// so j always indexes the force; T is stored as T[i][j][k].
#include <cmath>

namespace capsula::greens {

/// Stokeslet G_ij = delta_ij / r + xh_i xh_j / r^3 (eq 3.11), xh = x - x0 != 0.
inline void stokesletFreeSpace3D(const double xh[3], double G[3][3])
{
  const double r2 = xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2];
  const double invR = 1.0 / std::sqrt(r2);
  const double invR3 = invR / r2;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      G[i][j] = xh[i] * xh[j] * invR3;
    }
    G[i][i] += invR;
  }
}

/// Stresslet T_ijk = -6 xh_i xh_j xh_k / r^5 (eq 3.12), xh = x - x0 != 0.
inline void stressletFreeSpace3D(const double xh[3], double T[3][3][3])
{
  const double r2 = xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2];
  const double scale = -6.0 / (r2 * r2 * std::sqrt(r2));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        T[i][j][k] = scale * xh[i] * xh[j] * xh[k];
      }
    }
  }
}

/// Pressure vector P_j = 2 xh_j / r^3 of the Stokeslet, so that
/// T_ijk = -P_j delta_ik + dG_ij/dx_k + dG_kj/dx_i.
inline void pressureFreeSpace3D(const double xh[3], double P[3])
{
  const double r2 = xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2];
  const double scale = 2.0 / (r2 * std::sqrt(r2));
  for (int j = 0; j < 3; ++j) {
    P[j] = scale * xh[j];
  }
}

/// Kernel policy for operators templated on the Green's function.
struct FreeSpace3D {
  static constexpr int dimension = 3;
  static constexpr const char* name = "free-space 3D";

  /// G_ij(x, x0): velocity at field point x of a unit force along j at pole x0.
  static void stokeslet(const double x[3], const double x0[3], double G[3][3])
  {
    const double xh[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    stokesletFreeSpace3D(xh, G);
  }
  /// T_ijk(x, x0): stress sigma_ik at field point x of a unit force along j at pole x0.
  static void stresslet(const double x[3], const double x0[3], double T[3][3][3])
  {
    const double xh[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    stressletFreeSpace3D(xh, T);
  }
  /// P_j(x, x0): pressure at field point x of a unit force along j at pole x0.
  static void pressure(const double x[3], const double x0[3], double P[3])
  {
    const double xh[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    pressureFreeSpace3D(xh, P);
  }
};

} // namespace capsula::greens
