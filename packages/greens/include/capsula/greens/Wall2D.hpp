#pragma once
// Stokes flow of a point force above a plane wall in 2D (thesis App. B.1; Pozrikidis 1992,
// section 2.5), the 2D analogue of Wall3D.hpp.
//
// Wall y = 0, fluid y > 0; pole x0 at height h = y0 > 0, image pole x0' = (x0, -h);
// xh = x - x0, X = x - x0' (field point from the IMAGE pole), R = |X|, s_j = imageSign(j):
//   G^W = G^FS(xh) - G^FS(X) + 2 h^2 G^D(X) - 2 h G^SD(X)                        (B.1-B.2)
//   G^D_ij  = s_j (delta_ij / R^2 - 2 X_i X_j / R^4)                              (B.3)
//   G^SD_ij = X_2 G^D_ij + s_j (delta_j2 X_i - delta_i2 X_j) / R^2                 (B.4)
//   T^W = T^FS(xh) - T^FS(X) + 2 h^2 T^D(X) - 2 h T^SD(X)                        (B.5-B.6)
//   T^D_ijk  = 4 s_j (-(delta_ik X_j + delta_ij X_k + delta_kj X_i) / R^4 + 4 X_i X_j X_k / R^6)
//   T^SD_ijk = X_2 T^D_ijk + 4 s_j (delta_ik X_j X_2 - delta_j2 X_i X_k) / R^4
// T^D is B.7 evaluated. In B.8 the pressure term -2 delta_ik x_j / r^2 is not the doublet's:
// its pressure is P^SD_j = 2 s_j (delta_j2 / R^2 - 2 X_j X_2 / R^4), which T^SD above
// includes (derived symbolically; pinned by the tests: T = -P delta + grad G + grad G^T,
// momentum balance, traction identities). "2" is the normal axis (index 1 here).
// Normalisation and index roles as in FreeSpace2D.hpp; the image terms are shared with
// Wall3D.hpp (PlaneWall.hpp).
#include <capsula/greens/FreeSpace2D.hpp>
#include <capsula/greens/PlaneWall.hpp>

#include <cmath>

namespace capsula::greens {

/// G^W_ij(x, x0) above the wall y = 0; needs x0[1] > 0, x[1] >= 0, x != x0.
inline void stokesletWall2D(const double x[2], const double x0[2], double G[2][2])
{
  double xh[2], X[2];
  poleAndImageSeparations<2>(x, x0, xh, X);
  const double R2 = X[0] * X[0] + X[1] * X[1];
  const double invR2 = 1.0 / R2;
  const double invR4 = invR2 * invR2;
  const double minusLogR = -0.5 * std::log(R2);

  stokesletFreeSpace2D(xh, G);
  addStokesletImages<2>(X, x0[wallNormalAxis], minusLogR, invR2, invR4, G);
}

/// T^W_ijk(x, x0) above the wall y = 0 (stress sigma_ik at x, force along j at x0).
inline void stressletWall2D(const double x[2], const double x0[2], double T[2][2][2])
{
  double xh[2], X[2];
  poleAndImageSeparations<2>(x, x0, xh, X);
  const double R2 = X[0] * X[0] + X[1] * X[1];
  const double invR4 = 1.0 / (R2 * R2);
  const double invR6 = invR4 / R2;

  stressletFreeSpace2D(xh, T);
  addStressletImages<2>(X, x0[wallNormalAxis], invR4, invR6, T);
}

/// P^W_j(x, x0) = P^FS_j(xh) - P^FS_j(X) - 2 h P^SD_j(X) (the potential dipole has none).
inline void pressureWall2D(const double x[2], const double x0[2], double P[2])
{
  double xh[2], X[2];
  poleAndImageSeparations<2>(x, x0, xh, X);
  const double invR2 = 1.0 / (X[0] * X[0] + X[1] * X[1]);
  const double invR4 = invR2 * invR2;

  pressureFreeSpace2D(xh, P);
  addPressureImages<2>(X, x0[wallNormalAxis], invR2, invR4, P);
}

/// Kernel policy for operators templated on the Green's function.
struct Wall2D {
  static constexpr int dimension = 2;
  static constexpr const char* name = "plane wall 2D";

  static void stokeslet(const double x[2], const double x0[2], double G[2][2]) { stokesletWall2D(x, x0, G); }
  static void stresslet(const double x[2], const double x0[2], double T[2][2][2]) { stressletWall2D(x, x0, T); }
  static void pressure(const double x[2], const double x0[2], double P[2]) { pressureWall2D(x, x0, P); }
};

} // namespace capsula::greens
