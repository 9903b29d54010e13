#pragma once
// The plane wall of the wall-bounded kernels: the plane y = 0, fluid in y > 0
// (thesis App. B with w = 0). Coordinate axis 1 (y) is the wall normal in 2D and 3D.
//
// The image system has the same shape in both dimensions (eqs B.1-B.8 in 2D, B.9-B.16 in
// 3D): G^W = G^FS(xh) - G^FS(X) + 2 h^2 G^D(X) - 2 h G^SD(X), and likewise T^W and P^W,
// with xh = x - x0 from the pole, X = x - x0' from its image x0' = (x0, -h, z0), R = |X|.
// Only the free-space kernels and the powers of 1/R depend on the dimension D: the
// potential dipole G^D falls like 1/R^D, its stress like 1/R^(D+1). The functions below
// add the image terms shared by Wall2D.hpp and Wall3D.hpp, given those powers.

namespace capsula::greens {

inline constexpr int wallNormalAxis = 1;

/// The "+-" of thesis eqs B.3-B.4, B.11-B.12, B.15-B.16: +1 when the force index j is
/// tangential to the wall, -1 when it is normal.
inline constexpr double imageSign(int j)
{
  return j == wallNormalAxis ? -1.0 : 1.0;
}

/// xh = x - x0 (field point from the pole x0) and X = x - x0' (from its image below the wall).
template <int D>
inline void poleAndImageSeparations(const double x[D], const double x0[D], double xh[D], double X[D])
{
  for (int i = 0; i < D; ++i) {
    xh[i] = x[i] - x0[i];
    X[i] = i == wallNormalAxis ? x[i] + x0[i] : x[i] - x0[i];
  }
}

/// G += -G^FS(X) + 2 h^2 G^D(X) - 2 h G^SD(X) (eqs B.2-B.4, B.10-B.12), from
/// `imageDiagonal` (the diagonal term of G^FS(X): -log R in 2D, 1/R in 3D), invRD = 1/R^D
/// and invRD2 = 1/R^(D+2):
///   G^D_ij  = s_j (delta_ij / R^D - D X_i X_j / R^(D+2)),
///   G^SD_ij = X_2 G^D_ij + s_j (delta_j2 X_i - delta_i2 X_j) / R^D.
template <int D>
inline void addStokesletImages(const double X[D], double h, double imageDiagonal, double invRD, double invRD2,
                               double G[D][D])
{
  constexpr double d = D;
  const double Xn = X[wallNormalAxis];
  for (int i = 0; i < D; ++i) {
    for (int j = 0; j < D; ++j) {
      const double s = imageSign(j);
      const double dij = (i == j) ? 1.0 : 0.0;
      const double imageStokeslet = dij * imageDiagonal + X[i] * X[j] * invRD;
      const double dipole = s * (dij * invRD - d * X[i] * X[j] * invRD2);
      const double doublet =
          Xn * dipole + s * ((j == wallNormalAxis ? X[i] : 0.0) - (i == wallNormalAxis ? X[j] : 0.0)) * invRD;
      G[i][j] += -imageStokeslet + 2.0 * h * h * dipole - 2.0 * h * doublet;
    }
  }
}

/// T += -T^FS(X) + 2 h^2 T^D(X) - 2 h T^SD(X) (eqs B.5-B.8, B.13-B.16), from
/// invRD2 = 1/R^(D+2) and invRD4 = 1/R^(D+4):
///   T^FS_ijk(X) = -2D X_i X_j X_k / R^(D+2),
///   T^D_ijk  = 2D s_j (-(delta_ik X_j + delta_ij X_k + delta_kj X_i) / R^(D+2) + (D+2) X_i X_j X_k / R^(D+4)),
///   T^SD_ijk = X_2 T^D_ijk + 2D s_j (delta_ik X_j X_2 - delta_j2 X_i X_k) / R^(D+2).
template <int D>
inline void addStressletImages(const double X[D], double h, double invRD2, double invRD4, double T[D][D][D])
{
  constexpr double twoD = 2.0 * D;
  constexpr double dPlusTwo = D + 2.0;
  const double Xn = X[wallNormalAxis];
  for (int i = 0; i < D; ++i) {
    for (int j = 0; j < D; ++j) {
      const double s = imageSign(j);
      for (int k = 0; k < D; ++k) {
        const double Xijk = X[i] * X[j] * X[k];
        const double deltaTerms = (i == k ? X[j] : 0.0) + (i == j ? X[k] : 0.0) + (k == j ? X[i] : 0.0);
        const double imageStresslet = -twoD * Xijk * invRD2;
        const double dipole = twoD * s * (-deltaTerms * invRD2 + dPlusTwo * Xijk * invRD4);
        const double doublet =
            Xn * dipole + twoD * s * ((i == k ? X[j] * Xn : 0.0) - (j == wallNormalAxis ? X[i] * X[k] : 0.0)) * invRD2;
        T[i][j][k] += -imageStresslet + 2.0 * h * h * dipole - 2.0 * h * doublet;
      }
    }
  }
}

/// P += -P^FS(X) - 2 h P^SD(X) (the potential dipole has no pressure), from invRD = 1/R^D
/// and invRD2 = 1/R^(D+2): P^FS_j(X) = 2 X_j / R^D, P^SD_j = 2 s_j (delta_j2 / R^D - D X_j X_2 / R^(D+2)).
template <int D>
inline void addPressureImages(const double X[D], double h, double invRD, double invRD2, double P[D])
{
  constexpr double d = D;
  const double Xn = X[wallNormalAxis];
  for (int j = 0; j < D; ++j) {
    const double doublet = 2.0 * imageSign(j) * ((j == wallNormalAxis ? invRD : 0.0) - d * X[j] * Xn * invRD2);
    P[j] += -2.0 * X[j] * invRD - 2.0 * h * doublet;
  }
}

} // namespace capsula::greens
