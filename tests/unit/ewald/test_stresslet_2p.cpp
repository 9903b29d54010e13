// The stresslet's split (StressletSplit.hpp) and its reference 2P Ewald sum
// (StressletReference2P.hpp): the stress of the split and of the periodic Stokeslet.
#include <capsula/ewald/EwaldSplit.hpp>
#include <capsula/ewald/StressletReference2P.hpp>
#include <capsula/ewald/StressletSplit.hpp>
#include <capsula/greens/FreeSpace3D.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace {

using namespace capsula::ewald;
constexpr double stressletTestPi = 3.14159265358979323846;

using StokesletOf = std::function<void(const double[3], double[3][3])>;

/// d_k G_ij + d_i G_kj at xh by central differences of step h (error ~h^2 |d^3 G|).
void symmetricGradient(const StokesletOf& stokeslet, const double xh[3], double h, double out[3][3][3])
{
  double dG[3][3][3]; // dG[k][i][j] = d_k G_ij
  for (int k = 0; k < 3; ++k) {
    double plus[3] = {xh[0], xh[1], xh[2]}, minus[3] = {xh[0], xh[1], xh[2]};
    plus[k] += h;
    minus[k] -= h;
    double Gp[3][3], Gm[3][3];
    stokeslet(plus, Gp);
    stokeslet(minus, Gm);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        dG[k][i][j] = (Gp[i][j] - Gm[i][j]) / (2.0 * h);
      }
    }
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        out[i][j][k] = dG[k][i][j] + dG[i][k][j];
      }
    }
  }
}

TEST(StressletSplit, LocalPartIsTheStressOfTheLocalStokeslet)
{
  // T^R = -P^R_j delta_ik + d_k G^R_ij + d_i G^R_kj with P^R of the header; central differences
  // with h = 1e-4 r are accurate to ~1e-8 |T|: 1e-6 catches any wrong coefficient (the Gaussian
  // terms are O(xi^3 r) of |T| ~ 1/r^2 at xi r ~ 1).
  const double points[3][3] = {{0.3, -0.2, 0.1}, {-0.6, 0.5, 0.4}, {0.9, 0.7, -1.1}};
  for (double xi : {0.8, 2.5}) {
    for (const auto& xh : points) {
      const double r = std::sqrt(xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2]);
      double T[3][3][3], grad[3][3][3];
      screenedStresslet3D(xh, xi, T);
      symmetricGradient([xi](const double x[3], double G[3][3]) { screenedStokeslet3D(x, xi, G); }, xh, 1e-4 * r, grad);
      const double p = 2.0 * std::erfc(xi * r) / (r * r * r) +
                       4.0 * xi / std::sqrt(stressletTestPi) * (1.0 / (r * r) - xi * xi) * std::exp(-xi * xi * r * r);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          for (int k = 0; k < 3; ++k) {
            const double expected = grad[i][j][k] - (i == k ? p * xh[j] : 0.0);
            EXPECT_NEAR(T[i][j][k], expected, 1e-6 / (r * r)) << "xi " << xi << " r " << r;
          }
        }
      }
    }
  }
}

TEST(StressletSplit, SmoothRemainderVanishesAtThePole)
{
  // T - T^R = T^F is odd and entire: O(xi^4 r) near r = 0 (T ~ 1/r^2 there, 1e6 at r = 1e-3, so
  // rounding is ~1e-10); 3 xi^4 r bounds the linear term's coefficients (4 xi^3/sqrt(pi) * xi... ).
  for (double xi : {0.5, 2.0}) {
    const double xh[3] = {0.6e-3, 0.0, 0.8e-3};
    double T[3][3][3], TR[3][3][3];
    capsula::greens::stressletFreeSpace3D(xh, T);
    screenedStresslet3D(xh, xi, TR);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(T[i][j][k] - TR[i][j][k], 0.0, 10.0 * xi * xi * xi * 1e-3);
        }
      }
    }
  }
}

TEST(StressletSplit, SmoothPartTransformIsTheStressOfTheSmoothStokeslet)
{
  // T^F^ = i [k_k G^F^_ij + k_i G^F^_kj + 8 pi gamma^ delta_ik k_j / k^2] (the transform of
  // -P_j delta_ik + d_k G_ij + d_i G_kj with P^F^ = -8 pi i k_j gamma^ / k^2).
  const double k[3] = {0.9, -0.4, 1.3};
  const double xi = 1.1;
  double R[3][3][3], G[3][3];
  smoothStressletFourier3D(k, xi, R);
  smoothStokesletFourier3D(k, xi, G);
  const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int l = 0; l < 3; ++l) {
        const double pressure = i == l ? 8.0 * stressletTestPi * hasimotoScreening(k2, xi) * k[j] / k2 : 0.0;
        EXPECT_NEAR(R[i][j][l], k[l] * G[i][j] + k[i] * G[l][j] + pressure, 1e-12);
      }
    }
  }
}

const PeriodicLayer stressletLayer{2.0, 1.5};
const double stressletPoints[3][3] = {{0.3, 0.4, -0.2}, {-0.9, -0.7, 0.6}, {1.9, 0.05, 1.4}};

double largestEntry(const double T[3][3][3])
{
  double m = 0.0;
  for (int i = 0; i < 27; ++i) {
    m = std::max(m, std::fabs((&T[0][0][0])[i]));
  }
  return m;
}

TEST(PeriodicStresslet2P, IsTheStressOfThePeriodicStokeslet)
{
  // T_ijk - delta_ik T_ljl / 3 = d_k G_ij + d_i G_kj (the trace over i = k gives -3 P_j, G being
  // divergence-free), G the periodic Stokeslet (Ewald2PReference) differentiated by central
  // differences (h = 1e-4: error ~1e-8 plus rounding 1e-12 / 1e-4): ties the modes and the zero
  // mode of the two sums together. 1e-6 of |T|.
  const EwaldTruncation truncation = ewaldTruncation(1.5, 1e-16);
  for (const auto& xh : stressletPoints) {
    double T[3][3][3], grad[3][3][3];
    periodicStresslet2P(stressletLayer, truncation, xh, T);
    symmetricGradient([&](const double x[3], double G[3][3]) { periodicStokeslet2P(stressletLayer, truncation, x, G); },
                      xh, 1e-4, grad);
    const double scale = largestEntry(T);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          const double trace = (T[0][j][0] + T[1][j][1] + T[2][j][2]) / 3.0;
          EXPECT_NEAR(T[i][j][k] - (i == k ? trace : 0.0), grad[i][j][k], 1e-6 * scale)
              << "(" << i << "," << j << "," << k << ")";
        }
      }
    }
  }
}

TEST(PeriodicStresslet2P, IndependentOfTheSplittingParameterAndPeriodic)
{
  // As for the Stokeslet: xi = 1, 2, 4 agree to 1e-12 of |T|, a lattice shift to 1e-13.
  for (const auto& xh : stressletPoints) {
    double reference[3][3][3];
    periodicStresslet2P(stressletLayer, ewaldTruncation(1.0, 1e-16), xh, reference);
    const double scale = largestEntry(reference);
    for (double xi : {2.0, 4.0}) {
      double T[3][3][3];
      periodicStresslet2P(stressletLayer, ewaldTruncation(xi, 1e-16), xh, T);
      for (int e = 0; e < 27; ++e) {
        EXPECT_NEAR((&T[0][0][0])[e], (&reference[0][0][0])[e], 1e-12 * scale) << "xi " << xi;
      }
    }
    const double moved[3] = {xh[0] - 2.0 * stressletLayer.lengthX, xh[1], xh[2] + stressletLayer.lengthZ};
    double T[3][3][3];
    periodicStresslet2P(stressletLayer, ewaldTruncation(1.0, 1e-16), moved, T);
    for (int e = 0; e < 27; ++e) {
      EXPECT_NEAR((&T[0][0][0])[e], (&reference[0][0][0])[e], 1e-13 * scale);
    }
  }
}

TEST(PeriodicStresslet2P, AverageOverTheCellIsTheDocumentedZeroMode)
{
  // -4 pi sign(y) / A on xxy, xyx, yxx, zzy, zyz, yzz, yyy; 0 elsewhere (24 x 24 trapezoidal
  // average, exact to ~e^{-24 (2 pi / L) |y|} as for the Stokeslet).
  const double area = stressletLayer.lengthX * stressletLayer.lengthZ;
  for (double y : {0.8, -1.4}) {
    double average[3][3][3] = {};
    const int n = 24;
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        const double xh[3] = {a * stressletLayer.lengthX / n, y, b * stressletLayer.lengthZ / n};
        double T[3][3][3];
        periodicStresslet2P(stressletLayer, ewaldTruncation(1.5, 1e-14), xh, T);
        for (int e = 0; e < 27; ++e) {
          (&average[0][0][0])[e] += (&T[0][0][0])[e] / (n * n);
        }
      }
    }
    const double value = -4.0 * stressletTestPi * (y > 0 ? 1.0 : -1.0) / area;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          const int ys = (i == 1) + (j == 1) + (k == 1);
          const bool pairEqual = (ys == 1 && ((i == 1 && j == k) || (j == 1 && i == k) || (k == 1 && i == j)));
          const double expected = (pairEqual || ys == 3) ? value : 0.0;
          EXPECT_NEAR(average[i][j][k], expected, 1e-11) << "y " << y << " (" << i << j << k << ")";
        }
      }
    }
  }
}

} // namespace
