// Hasimoto's split of the Stokeslet (EwaldSplit.hpp): the local part plus the inverse transform
// of the smooth part is the Stokeslet, the smooth part is finite at the pole, the local part
// decays like e^{-xi^2 r^2}.
#include <capsula/ewald/EwaldSplit.hpp>
#include <capsula/greens/FreeSpace3D.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace capsula::ewald;
constexpr double splitPi = 3.14159265358979323846;

/// G^F(xh) by the 3D inverse transform of G^F^ reduced to one radial integral: the angular
/// average of (delta - khat khat) e^{i k.x} is (j0 - j1/z) delta + j2 xhat xhat (z = k r), so
///   G^F_ij = (4/pi) int_0^inf gamma^(k) [(j0 - j1/z) delta_ij + j2 xhat_i xhat_j] dk.
/// Composite Simpson on [0, 2 xi * 7] (gamma^ < 1e-19 beyond), 20000 intervals.
void smoothPartByRadialQuadrature(const double xh[3], double xi, double G[3][3])
{
  const double r = std::sqrt(xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2]);
  const int intervals = 20000;
  const double kMax = 14.0 * xi;
  const double h = kMax / intervals;
  double isotropic = 0.0, directional = 0.0;
  for (int q = 0; q <= intervals; ++q) {
    const double k = q * h;
    const double weight = (q == 0 || q == intervals) ? 1.0 : (q % 2 == 1 ? 4.0 : 2.0);
    const double z = k * r;
    // j0 - j1/z and j2 with their series near z = 0 (2/3 - z^2/15 and z^2/15).
    const double j0MinusJ1OverZ =
        z < 1e-3 ? 2.0 / 3.0 - z * z / 15.0 : std::sph_bessel(0, z) - std::sph_bessel(1, z) / z;
    const double j2 = z < 1e-3 ? z * z / 15.0 : std::sph_bessel(2, z);
    const double screening = hasimotoScreening(k * k, xi);
    isotropic += weight * screening * j0MinusJ1OverZ;
    directional += weight * screening * j2;
  }
  isotropic *= 4.0 / splitPi * h / 3.0;
  directional *= 4.0 / splitPi * h / 3.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      G[i][j] = directional * xh[i] * xh[j] / (r * r) + (i == j ? isotropic : 0.0);
    }
  }
}

TEST(EwaldSplit, LocalPartPlusInverseTransformOfSmoothPartIsTheStokeslet)
{
  // The split is exact: G^R + G^F = G at every point, for any xi. The Simpson sum is accurate
  // to ~1e-13 here (the integrand is entire and Gaussian-damped), so 1e-10 of |G| catches any
  // wrong factor in G^R or G^F^ (a factor 2 on the Gaussian term moves G^R by ~xi e^{-xi^2 r^2}).
  const double points[4][3] = {{0.05, 0.0, 0.02}, {0.3, -0.2, 0.1}, {-0.6, 0.5, 0.4}, {1.2, 0.9, -1.5}};
  for (double xi : {0.7, 2.0, 3.5}) {
    for (const auto& xh : points) {
      double G[3][3], GR[3][3], GF[3][3];
      capsula::greens::stokesletFreeSpace3D(xh, G);
      screenedStokeslet3D(xh, xi, GR);
      smoothPartByRadialQuadrature(xh, xi, GF);
      const double r = std::sqrt(xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2]);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          EXPECT_NEAR(GR[i][j] + GF[i][j], G[i][j], 1e-10 * (2.0 / r))
              << "xi " << xi << " r " << r << " (" << i << "," << j << ")";
        }
      }
    }
  }
}

TEST(EwaldSplit, SmoothRemainderIsFiniteAtThePole)
{
  // G - G^R = 4 xi / sqrt(pi) delta - (8 xi^3 / (3 sqrt(pi))) r^2 delta + (4 xi^3 / (3 sqrt(pi))) xh xh
  // + O(r^4) (Taylor series of the closed form); at r = 1e-3 the O(r^4) rest is ~1e-11 xi^5 and
  // rounding in 1/r - erfc(xi r)/r is ~1e3 * 1e-16, so 1e-9 separates the r^2 terms (~1e-6).
  for (double xi : {0.5, 2.0}) {
    const double xh[3] = {0.6e-3, -0.0e-3, 0.8e-3};
    const double r2 = 1e-6;
    double G[3][3], GR[3][3];
    capsula::greens::stokesletFreeSpace3D(xh, G);
    screenedStokeslet3D(xh, xi, GR);
    const double invSqrtPi = 1.0 / std::sqrt(splitPi);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double expected = (i == j ? 4.0 * xi * invSqrtPi - 8.0 * xi * xi * xi * invSqrtPi * r2 / 3.0 : 0.0) +
                                4.0 * xi * xi * xi * invSqrtPi / 3.0 * xh[i] * xh[j];
        EXPECT_NEAR(G[i][j] - GR[i][j], expected, 1e-9) << "xi " << xi << " (" << i << "," << j << ")";
      }
    }
    EXPECT_NEAR(smoothStokesletAtPole(xi), 4.0 * xi * invSqrtPi, 1e-15);
  }
}

TEST(EwaldSplit, LocalPartDecaysLikeAGaussian)
{
  // G^R = a delta + b xh xh with a e^{xi^2 r^2} -> -2 xi / sqrt(pi) and b r^2 e^{xi^2 r^2} ->
  // +2 xi / sqrt(pi), both with relative corrections 1 / (2 (xi r)^2) + O((xi r)^-4) from erfc's
  // asymptotic series; a decay e^{-c xi^2 r^2} with c != 1 would leave ratios off by e^{(1-c) 16}.
  for (double xi : {0.8, 3.0}) {
    for (double s : {4.0, 5.0, 6.0}) {
      const double r = s / xi;
      double a = 0.0, b = 0.0;
      screenedStokesletCoefficients(r, xi, a, b);
      const double scale = 2.0 * xi / std::sqrt(splitPi) * std::exp(-s * s);
      const double correction = 1.0 / (2.0 * s * s);
      EXPECT_NEAR(a / scale, -1.0 + correction, 1.5 / (s * s * s * s)) << "xi r = " << s;
      EXPECT_NEAR(b * r * r / scale, 1.0 + correction, 1.5 / (s * s * s * s)) << "xi r = " << s;
    }
  }
}

TEST(EwaldSplit, SmoothPartTransformIsTransverseAndScreened)
{
  // G^F^ k = 0 (incompressible) and trace G^F^ = 16 pi gamma^(k) / k^2 (trace of delta k^2 - k k
  // is 2 k^2); gamma^(k) = (1 + k^2/(4 xi^2)) e^{-k^2/(4 xi^2)} at k = 2 xi is 2/e.
  const double k[3] = {0.7, -1.1, 0.4};
  const double xi = 0.9;
  double Ghat[3][3];
  smoothStokesletFourier3D(k, xi, Ghat);
  const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(Ghat[i][0] * k[0] + Ghat[i][1] * k[1] + Ghat[i][2] * k[2], 0.0, 1e-13);
  }
  EXPECT_NEAR(Ghat[0][0] + Ghat[1][1] + Ghat[2][2], 16.0 * splitPi * hasimotoScreening(k2, xi) / k2, 1e-12);
  EXPECT_NEAR(hasimotoScreening(4.0 * xi * xi, xi), 2.0 / std::exp(1.0), 1e-15);
}

} // namespace
