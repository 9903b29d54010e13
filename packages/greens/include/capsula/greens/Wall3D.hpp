#pragma once
// Stokes flow of a point force above a plane wall in 3D: Blake's (1971) image system in
// the form of Pozrikidis (1992, section 2.5), thesis App. B.2 with the ERRATA fixes.
//
// Wall y = 0, fluid y > 0 (PlaneWall.hpp); pole x0 with height h = y0 > 0, image pole
// x0' = (x0, -h, z0). With xh = x - x0 and X = x - x0' (field point from the IMAGE pole),
// R = |X|, s_j = imageSign(j):
//   G^W = G^FS(xh) - G^FS(X) + 2 h^2 G^D(X) - 2 h G^SD(X)                        (B.9-B.10)
//   G^D_ij  = s_j (delta_ij / R^3 - 3 X_i X_j / R^5)                              (B.11)
//   G^SD_ij = X_2 G^D_ij + s_j (delta_j2 X_i - delta_i2 X_j) / R^3                 (B.12)
// and the stress of that flow, with the 3D free-space stresslet (ERRATA, eq 3.12):
//   T^W = T^FS(xh) - T^FS(X) + 2 h^2 T^D(X) - 2 h T^SD(X)                        (B.13-B.14)
//   T^D_ijk  = 6 s_j (-(delta_ik X_j + delta_ij X_k + delta_kj X_i) / R^5 + 5 X_i X_j X_k / R^7)
//   T^SD_ijk = X_2 T^D_ijk + 6 s_j (delta_ik X_j X_2 - delta_j2 X_i X_k) / R^5
// T^D = dG^D_ij/dx_k + dG^D_kj/dx_i carries a factor 6 that B.15 as printed lacks; T^SD
// includes the doublet's pressure P^SD_j = 2 s_j (delta_j2 / R^3 - 3 X_j X_2 / R^5). Both
// were derived symbolically and are pinned by the tests (T = -P delta + grad G + grad G^T,
// momentum balance, traction identities). "2" above is the normal axis (index 1 here).
// Normalisation and index roles as in FreeSpace3D.hpp; the image terms are shared with
// Wall2D.hpp (PlaneWall.hpp). The wall pole correction at x = x0,
// G^W - G^FS = -3/(4h) tangential, -3/(2h) normal, is the classical 9/16 and 9/8 a/h law.
#include <capsula/greens/FreeSpace3D.hpp>
#include <capsula/greens/PlaneWall.hpp>

#include <cmath>

namespace capsula::greens {

/// G^W_ij(x, x0) above the wall y = 0; needs x0[1] > 0, x[1] >= 0, x != x0.
inline void stokesletWall3D(const double x[3], const double x0[3], double G[3][3])
{
  double xh[3], X[3];
  poleAndImageSeparations<3>(x, x0, xh, X);
  const double R2 = X[0] * X[0] + X[1] * X[1] + X[2] * X[2];
  const double invR = 1.0 / std::sqrt(R2);
  const double invR3 = invR / R2;
  const double invR5 = invR3 / R2;

  stokesletFreeSpace3D(xh, G);
  addStokesletImages<3>(X, x0[wallNormalAxis], invR, invR3, invR5, G);
}

/// T^W_ijk(x, x0) above the wall y = 0 (stress sigma_ik at x, force along j at x0).
inline void stressletWall3D(const double x[3], const double x0[3], double T[3][3][3])
{
  double xh[3], X[3];
  poleAndImageSeparations<3>(x, x0, xh, X);
  const double R2 = X[0] * X[0] + X[1] * X[1] + X[2] * X[2];
  const double invR5 = 1.0 / (R2 * R2 * std::sqrt(R2));
  const double invR7 = invR5 / R2;

  stressletFreeSpace3D(xh, T);
  addStressletImages<3>(X, x0[wallNormalAxis], invR5, invR7, T);
}

/// P^W_j(x, x0) = P^FS_j(xh) - P^FS_j(X) - 2 h P^SD_j(X) (the potential dipole has none).
inline void pressureWall3D(const double x[3], const double x0[3], double P[3])
{
  double xh[3], X[3];
  poleAndImageSeparations<3>(x, x0, xh, X);
  const double R2 = X[0] * X[0] + X[1] * X[1] + X[2] * X[2];
  const double invR3 = 1.0 / (R2 * std::sqrt(R2));
  const double invR5 = invR3 / R2;

  pressureFreeSpace3D(xh, P);
  addPressureImages<3>(X, x0[wallNormalAxis], invR3, invR5, P);
}

/// Kernel policy for operators templated on the Green's function.
struct Wall3D {
  static constexpr int dimension = 3;
  static constexpr const char* name = "plane wall 3D";

  static void stokeslet(const double x[3], const double x0[3], double G[3][3]) { stokesletWall3D(x, x0, G); }
  static void stresslet(const double x[3], const double x0[3], double T[3][3][3]) { stressletWall3D(x, x0, T); }
  static void pressure(const double x[3], const double x0[3], double P[3]) { pressureWall3D(x, x0, P); }
};

} // namespace capsula::greens
