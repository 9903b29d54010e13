// The reference 2P sum of the lower wall's stresslet (WallStresslet2P.hpp): the screened third
// derivatives of 1/r against finite differences; the stress of the periodic wall Stokeslet,
// periodicity, independence of the splitting parameter, the zero mode as the cell average, and
// Blake's single-source stress (greens/Wall3D.hpp) as the cell grows.
#include <capsula/ewald/LaplaceSplit.hpp>
#include <capsula/ewald/WallStokeslet2P.hpp>
#include <capsula/ewald/WallStresslet2P.hpp>
#include <capsula/greens/Wall3D.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wall_stresslet_2p_test {

using namespace capsula::ewald;
constexpr double wallStressTestPi = 3.14159265358979323846;

struct Stress {
  double t[3][3][3];
};

Stress wallT(const PeriodicLayer& layer, double xi, const double x[3], const double x0[3])
{
  Stress s;
  periodicWallStresslet2P(layer, ewaldTruncation(xi, 1e-16), x, x0, s.t);
  return s;
}

double maxAbs(const Stress& s)
{
  double m = 0.0;
  for (const auto& plane : s.t) {
    for (const auto& row : plane) {
      for (double v : row) {
        m = std::max(m, std::fabs(v));
      }
    }
  }
  return m;
}

double maxDifference(const Stress& a, const Stress& b)
{
  double m = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        m = std::max(m, std::fabs(a.t[i][j][k] - b.t[i][j][k]));
      }
    }
  }
  return m;
}

const PeriodicLayer stressCell{2.0, 1.5};
const double stressSources[3][3] = {{0.3, 0.05, 0.2}, {1.1, 0.5, 0.9}, {0.7, 1.3, 1.4}};
const double stressPoints[3][3] = {{0.9, 0.2, 0.6}, {-0.4, 1.7, 0.3}, {1.6, 0.02, 1.2}};

TEST(LaplaceSplit, ScreenedThirdDerivativesMatchFiniteDifferences)
{
  // Central differences of the hessian, step 1e-4 (truncation ~1e-8 relative): bound 1e-6.
  const double xi = 1.3, step = 1e-4;
  for (const auto& xh : stressPoints) {
    double third[3][3][3];
    screenedLaplaceThirdDerivatives3D(xh, xi, third);
    double scale = 0.0;
    for (const auto& plane : third) {
      for (const auto& row : plane) {
        for (double v : row) {
          scale = std::max(scale, std::fabs(v));
        }
      }
    }
    for (int k = 0; k < 3; ++k) {
      double plus[3] = {xh[0], xh[1], xh[2]}, minus[3] = {xh[0], xh[1], xh[2]};
      plus[k] += step;
      minus[k] -= step;
      double g[3], hPlus[3][3], hMinus[3][3];
      screenedLaplaceDerivatives3D(plus, xi, g, hPlus);
      screenedLaplaceDerivatives3D(minus, xi, g, hMinus);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          EXPECT_NEAR(third[i][j][k], (hPlus[i][j] - hMinus[i][j]) / (2.0 * step), 1e-6 * scale);
        }
      }
    }
  }
}

TEST(WallStresslet2P, IsTheStressOfThePeriodicWallStokeslet)
{
  // T_ijk + delta_ik P_j = d_k G_ij + d_i G_kj with P_j = -T_ljl / 3 (d_l G_lj = 0), the
  // derivatives of periodicWallStokeslet2P by central differences (step 1e-4: truncation ~1e-8,
  // rounding ~1e-12 of |G|); bound 1e-6 of |T|. A wrong sign or factor of an image term is O(1).
  const double step = 1e-4;
  const EwaldTruncation truncation = ewaldTruncation(1.5, 1e-16);
  for (int n = 0; n < 3; ++n) {
    const Stress T = wallT(stressCell, 1.5, stressPoints[n], stressSources[n]);
    double grad[3][3][3]; // grad[i][j][k] = d_k G_ij
    for (int k = 0; k < 3; ++k) {
      double plus[3] = {stressPoints[n][0], stressPoints[n][1], stressPoints[n][2]};
      double minus[3] = {plus[0], plus[1], plus[2]};
      plus[k] += step;
      minus[k] -= step;
      double Gp[3][3], Gm[3][3];
      periodicWallStokeslet2P(stressCell, truncation, plus, stressSources[n], Gp);
      periodicWallStokeslet2P(stressCell, truncation, minus, stressSources[n], Gm);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          grad[i][j][k] = (Gp[i][j] - Gm[i][j]) / (2.0 * step);
        }
      }
    }
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double pressure = -(T.t[0][j][0] + T.t[1][j][1] + T.t[2][j][2]) / 3.0;
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(T.t[i][j][k] + (i == k ? pressure : 0.0), grad[i][j][k] + grad[k][j][i], 1e-6 * maxAbs(T))
              << "point " << n << " (" << i << j << k << ")";
        }
      }
    }
  }
}

TEST(WallStresslet2P, PeriodicAndIndependentOfTheSplittingParameter)
{
  // A lattice shift: rounding of the phases (1e-13); xi = 0.8 and 3 against 1.5: truncation
  // (1e-16) and rounding of O(100) terms (1e-12 relative).
  for (int n = 0; n < 3; ++n) {
    const Stress T = wallT(stressCell, 1.5, stressPoints[n], stressSources[n]);
    const double moved[3] = {stressPoints[n][0] - 2.0 * stressCell.lengthX, stressPoints[n][1],
                             stressPoints[n][2] + stressCell.lengthZ};
    EXPECT_LT(maxDifference(wallT(stressCell, 1.5, moved, stressSources[n]), T), 1e-13 * maxAbs(T));
    for (double xi : {0.8, 3.0}) {
      EXPECT_LT(maxDifference(wallT(stressCell, xi, stressPoints[n], stressSources[n]), T), 1e-12 * maxAbs(T))
          << "xi " << xi;
    }
  }
}

TEST(WallStresslet2P, ZeroModeIsTheCellAverage)
{
  // The 32 x 32 trapezoid average (nearest singularity 0.4 off the plane: error
  // ~ e^{-2 pi 0.4 32 / 2} ~ 1e-17) is
  // 8 pi H(h - y) / A on xxy, xyx, yxx, zzy, zyz, yzz, yyy and 0 elsewhere; bound 1e-10.
  const double x0[3] = {0.4, 0.8, 0.3};
  const int grid = 32;
  const double area = stressCell.lengthX * stressCell.lengthZ;
  for (double y : {0.1, 0.4, 1.2, 2.5}) {
    Stress average{};
    for (int m = 0; m < grid; ++m) {
      for (int n = 0; n < grid; ++n) {
        const double x[3] = {stressCell.lengthX * m / grid, y, stressCell.lengthZ * n / grid};
        const Stress T = wallT(stressCell, 1.5, x, x0);
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            for (int k = 0; k < 3; ++k) {
              average.t[i][j][k] += T.t[i][j][k] / (grid * grid);
            }
          }
        }
      }
    }
    const double below = y < x0[1] ? 8.0 * wallStressTestPi / area : 0.0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          const int ys = (i == 1) + (j == 1) + (k == 1);
          const bool carries = ys == 3 || (ys == 1 && (i == j || j == k || i == k));
          EXPECT_NEAR(average.t[i][j][k], carries ? below : 0.0, 1e-10) << "y " << y << " (" << i << j << k << ")";
        }
      }
    }
  }
}

TEST(WallStresslet2P, TendsToBlakeAtTheRateOfTheImageSum)
{
  // Along the wall d_y of Blake's far field 12 h y rho_i rho_j / rho^5 is 12 h rho_i rho_j /
  // rho^5, so T^per - T^Blake = 6 S3 h / L^3 on xxy and yxx (S3 as in test_wall_stokeslet_2p)
  // up to an O((h/L)^2) relative correction; bounds 3e-2 at L = 16 and 8e-3 at L = 32.
  const double S3 = 9.0336216831009503;
  const double x0[3] = {0.2, 1.0, 0.1};
  const double x[3] = {0.4, 0.5, 0.25};
  double blake[3][3][3];
  capsula::greens::stressletWall3D(x, x0, blake);
  for (double length : {16.0, 32.0}) {
    const PeriodicLayer square{length, length};
    const Stress T = wallT(square, 3.0 / length, x, x0);
    const double predicted = 6.0 * S3 * x0[1] / (length * length * length);
    const double bound = length < 20.0 ? 3e-2 : 8e-3;
    std::printf("wall stresslet L %g: (T - Blake) / prediction xxy %.5f yxx %.5f zzy %.5f\n", length,
                (T.t[0][0][1] - blake[0][0][1]) / predicted, (T.t[1][0][0] - blake[1][0][0]) / predicted,
                (T.t[2][2][1] - blake[2][2][1]) / predicted);
    EXPECT_NEAR((T.t[0][0][1] - blake[0][0][1]) / predicted, 1.0, bound) << "L " << length;
    EXPECT_NEAR((T.t[1][0][0] - blake[1][0][0]) / predicted, 1.0, bound) << "L " << length;
    EXPECT_NEAR((T.t[2][2][1] - blake[2][2][1]) / predicted, 1.0, bound) << "L " << length;
  }
}

} // namespace wall_stresslet_2p_test
