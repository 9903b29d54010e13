#pragma once
// The hot loop of the 2D single layer (thesis eq A.35): the Gauss-Legendre sums of
// G_ij(x_p, x_t) (f dl)_i over every regular point p for every target node t at once.
//
// As in RegularSums.hpp, the loop over targets is innermost and has no reduction, so it
// vectorises without reassociating sums (each target adds its terms in point order), and
// it is compiled for AVX2 and AVX-512 besides the portable baseline (target_clones). The
// logarithm is VectorisableLog.hpp's, and the wall kernel takes one logarithm per pair:
// the free-space and image Stokeslets' -ln r + ln R combine into ln(R^2 / r^2) / 2, and
// 1 / r^2, 1 / R^2 come from one division. (Sharing the logarithm's division too, by
// reducing R^2 and r^2 separately, measured 35% slower: the extra bit work costs more.)
// A (segment, target) pair that the near-singular or the singular rules treat apart has
// mask 0 and adds nothing here (LayerPotentials2D adds it); every other pair has mask 1.
//
// The pair formulas are written out for u_j += G_ij f_i (pinned against
// greens::stokesletWall2D / stokesletFreeSpace2D by tests/unit/scene2d, RegularSums2D),
// and for the double-layer weights W_ij = T_ijk a_k of SplineDoubleLayer2D (pinned against
// greens::stressletWall2D / stressletFreeSpace2D).
#include <capsula/core/KernelClones.hpp>
#include <capsula/operators/RegularSums.hpp> // targetLaneMultiple
#include <capsula/operators/VectorisableLog.hpp>

namespace capsula::scene2d {

/// u_j += G^FS_ij(x, x0) f_i (eq A.8): G = -delta ln r + xh xh / r^2, xh = x - x0.
inline void addFreeSpaceStokesletPair2D(double x, double y, double fx, double fy, double x0, double y0, double& ux,
                                        double& uy)
{
  const double d0 = x - x0, d1 = y - y0;
  const double r2 = d0 * d0 + d1 * d1;
  // One division for 1 / r^2 and for the logarithm's f = (m - 1) / (m + 1).
  double e, m;
  operators::centredMantissa(r2, e, m);
  const double inverse = 1.0 / (r2 * (m + 1.0));
  const double invR2 = (m + 1.0) * inverse;
  const double minusLogR = -0.5 * operators::logFromReduced(e, (m - 1.0) * r2 * inverse);
  const double xf = (d0 * fx + d1 * fy) * invR2;
  ux += minusLogR * fx + xf * d0;
  uy += minusLogR * fy + xf * d1;
}

/// u_j += G^W_ij(x, x0) f_i above the wall y = 0 (eqs B.1-B.4, greens/Wall2D.hpp): with
/// xh = x - x0, X = x - x0' (x0' = (x0, -h), h = y0), r = |xh|, R = |X|, and because
/// 2 h^2 - 2 h X_y = -2 h y,
///   u_j += ln(R/r) f_j + (xh.f) xh_j / r^2 - (X.f) X_j / R^2
///          - 2 h y s_j (f_j / R^2 - 2 (X.f) X_j / R^4) - 2 h s_j (delta_jy (X.f) - f_y X_j) / R^2,
/// s_x = 1, s_y = -1 (greens::imageSign).
inline void addWallStokesletPair2D(double x, double y, double fx, double fy, double x0, double y0, double& ux,
                                   double& uy)
{
  const double h = y0;
  const double d0 = x - x0, d1 = y - y0;
  const double X1 = y + y0;
  const double r2 = d0 * d0 + d1 * d1;
  const double R2 = d0 * d0 + X1 * X1;
  const double invBoth = 1.0 / (r2 * R2); // one division for both reciprocals
  const double invr2 = R2 * invBoth;
  const double invR2 = r2 * invBoth;
  const double logRoverR = 0.5 * operators::vectorisableLog(R2 * invr2);
  const double xf = (d0 * fx + d1 * fy) * invr2;
  const double Xf = d0 * fx + X1 * fy;
  const double XfR2 = Xf * invR2;
  const double twoH = 2.0 * h;
  const double twoHy = twoH * y;
  const double twoXfR4 = 2.0 * XfR2 * invR2;
  ux += logRoverR * fx + xf * d0 - XfR2 * d0 - twoHy * (fx * invR2 - twoXfR4 * d0) + twoH * fy * d0 * invR2;
  uy += logRoverR * fy + xf * d1 - XfR2 * X1 + twoHy * (fy * invR2 - twoXfR4 * X1) + twoH * (Xf - fy * X1) * invR2;
}

/// W_ij = T^FS_ijk(x, x0) a_k = -4 xh_i xh_j (xh . a) / r^4 (eq A.9), [2 i + j]: the double-layer
/// weight of one point with a = n dl (SplineDoubleLayer2D.hpp).
inline void freeSpaceDoubleLayerWeight2D(double x, double y, double a0, double a1, double x0, double y0, double W[4])
{
  const double d0 = x - x0, d1 = y - y0;
  const double r2 = d0 * d0 + d1 * d1;
  const double scale = -4.0 * (d0 * a0 + d1 * a1) / (r2 * r2);
  W[0] = scale * d0 * d0;
  W[1] = scale * d0 * d1;
  W[2] = W[1];
  W[3] = scale * d1 * d1;
}

/// W_ij = T^W_ijk(x, x0) a_k above the wall y = 0 (eqs B.5-B.6, greens/Wall2D.hpp), [2 i + j]:
///   T^FS(xh) a - T^FS(X) a + 2 h^2 D - 2 h (X_y D + 4 s_j (a_i X_j X_y - delta_jy X_i (X.a)) / R^4),
///   D_ij = 4 s_j (-(a_i X_j + delta_ij (X.a) + a_j X_i) / R^4 + 4 X_i X_j (X.a) / R^6),
/// s_x = 1, s_y = -1, X = x - x0' (x0' = (x0, -h), h = y0).
inline void wallDoubleLayerWeight2D(double x, double y, double a0, double a1, double x0, double y0, double W[4])
{
  const double h = y0;
  const double d0 = x - x0, d1 = y - y0;
  const double X1 = y + y0;
  const double r2 = d0 * d0 + d1 * d1;
  const double R2 = d0 * d0 + X1 * X1;
  const double free = -4.0 * (d0 * a0 + d1 * a1) / (r2 * r2);
  const double invR2 = 1.0 / R2;
  const double invR4 = invR2 * invR2;
  const double Xa = d0 * a0 + X1 * a1;
  const double image = 4.0 * Xa * invR4;
  const double X[2] = {d0, X1};
  const double xh[2] = {d0, d1};
  const double a[2] = {a0, a1};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double s4 = j == 1 ? -4.0 : 4.0;
      const double dipole =
          s4 * (-(a[i] * X[j] + (i == j ? Xa : 0.0) + a[j] * X[i]) * invR4 + 4.0 * X[i] * X[j] * Xa * invR4 * invR2);
      const double doublet = X1 * dipole + s4 * (a[i] * X[j] * X1 - (j == 1 ? X[i] * Xa : 0.0)) * invR4;
      W[2 * i + j] = free * xh[i] * xh[j] + image * X[i] * X[j] + 2.0 * h * h * dipole - 2.0 * h * doublet;
    }
  }
}

/// The regular sums over `numSegments` segments of `pointsPerSegment` points each:
/// for every target t < paddedTargets,
///   ux[t], uy[t] += sum over segments k of mask[k paddedTargets + t] sum over the
///                   points p of k of G_ij(x_p, x_t) f_i,
/// with x_p = (px[p], py[p]), f = (fx[p], fy[p]) (already times dl), x_t = (tx[t], ty[t]).
/// paddedTargets is a multiple of targetLaneMultiple; padding lanes hold finite targets.
void addWallStokesletSums2D(const double* px, const double* py, const double* fx, const double* fy,
                            int pointsPerSegment, int numSegments, const double* tx, const double* ty,
                            int paddedTargets, const double* mask, double* ux, double* uy);
void addFreeSpaceStokesletSums2D(const double* px, const double* py, const double* fx, const double* fy,
                                 int pointsPerSegment, int numSegments, const double* tx, const double* ty,
                                 int paddedTargets, const double* mask, double* ux, double* uy);

/// The same pairs one by one: (ux[i], uy[i]) = G_ij(x_i, x0_i) f_i for i < count (the
/// pairs of the near-singular pieces, gathered so that they vectorise too).
void wallStokesletPairs2D(const double* x, const double* y, const double* fx, const double* fy, const double* x0,
                          const double* y0, int count, double* ux, double* uy);
void freeSpaceStokesletPairs2D(const double* x, const double* y, const double* fx, const double* fy, const double* x0,
                               const double* y0, int count, double* ux, double* uy);

/// The near-singular test of whole segments for every target at once: mask[k paddedTargets
/// + t] = 0 where target t, or its mirror image (t_x, -t_y) when `withImage`, is nearer
/// than sqrt(reach2[k]) to the start, middle or end of segment k, given as
/// segments[6 k .. 6 k + 5] = (a_x, a_y, m_x, m_y, b_x, b_y); 1 elsewhere. Squared
/// distances: the decision of LayerPotentials2D::isNear without square roots.
void markNearSegments2D(const double* segments, const double* reach2, int numSegments, const double* tx,
                        const double* ty, int paddedTargets, bool withImage, double* mask);

} // namespace capsula::scene2d
