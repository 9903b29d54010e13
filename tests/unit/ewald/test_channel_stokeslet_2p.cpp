// The reference Fourier series of the channel Stokeslet (ChannelStokeslet2P.hpp): no slip on
// both walls, periodicity, reciprocity, the reflection y -> H - y, a divergence-free flow, the
// zero mode as the cell average, and the lower wall's periodic Stokeslet (WallStokeslet2P.hpp)
// as the channel widens.
#include <capsula/ewald/ChannelStokeslet2P.hpp>
#include <capsula/ewald/WallStokeslet2P.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace channel_stokeslet_2p_test {

using namespace capsula::ewald;
constexpr double channelTestPi = 3.14159265358979323846;

struct Tensor {
  double g[3][3];
};

const PeriodicLayer cell{2.0, 1.5};
constexpr double height = 1.2;

Tensor channelG(double H, const double x[3], const double x0[3], const PeriodicLayer& layer = cell)
{
  Tensor t;
  periodicChannelStokeslet2P(layer, H, x, x0, t.g);
  return t;
}

double maxAbs(const Tensor& t)
{
  double m = 0.0;
  for (const auto& row : t.g) {
    for (double v : row) {
      m = std::max(m, std::fabs(v));
    }
  }
  return m;
}

const double sources[4][3] = {{0.3, 0.15, 0.2}, {1.1, 0.55, 0.9}, {0.7, 0.75, 1.4}, {1.9, 1.1, 0.1}};
const double fieldPoints[4][3] = {{0.9, 0.4, 0.6}, {-0.4, 0.95, 0.3}, {1.6, 0.3, 1.2}, {0.1, 0.35, -0.8}};

TEST(ChannelStokeslet2P, NoSlipOnBothWalls)
{
  // On y = 0 and y = H every mode vanishes by construction of its wall modes (4 x 4 solve) and
  // the zero mode by its profile; what is left is rounding of the series' terms (1e-15 each).
  for (const auto& x0 : sources) {
    const double inside[3] = {0.9, 0.5 * (x0[1] + (x0[1] > 0.6 ? 0.0 : height)), 0.6};
    const double scale = maxAbs(channelG(height, inside, x0));
    for (double y : {0.0, height}) {
      const double onWall[3] = {0.9, y, 0.6};
      EXPECT_LT(maxAbs(channelG(height, onWall, x0)), 1e-12 * scale) << "source height " << x0[1] << ", wall " << y;
    }
  }
}

TEST(ChannelStokeslet2P, PeriodicInXAndZ)
{
  // A lattice shift changes only the rounding of the phases (1e-15 relative per term).
  for (int n = 0; n < 4; ++n) {
    const Tensor G = channelG(height, fieldPoints[n], sources[n]);
    const double moved[3] = {fieldPoints[n][0] + 2.0 * cell.lengthX, fieldPoints[n][1],
                             fieldPoints[n][2] - cell.lengthZ};
    const Tensor shifted = channelG(height, moved, sources[n]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(shifted.g[i][j], G.g[i][j], 1e-12 * maxAbs(G));
      }
    }
  }
}

TEST(ChannelStokeslet2P, Reciprocity)
{
  // G_ij(x, x0) = G_ji(x0, x) (Lorentz reciprocity with no slip on both walls). Each mode is
  // reciprocal exactly, so the bound is rounding (1e-12 relative); a wrong sign in the
  // parallel-normal blocks (i k W_l vs i k W_y') breaks it at O(1).
  for (int n = 0; n < 4; ++n) {
    const Tensor G = channelG(height, fieldPoints[n], sources[n]);
    const Tensor swapped = channelG(height, sources[n], fieldPoints[n]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(G.g[i][j], swapped.g[j][i], 1e-12 * maxAbs(G)) << n << " (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(ChannelStokeslet2P, SymmetricUnderTheReflectionAcrossTheMidplane)
{
  // y -> H - y maps the channel onto itself: G_ij(Rx, Rx0) = s_i s_j G_ij(x, x0),
  // s = (1, -1, 1); the two sides are summed with different wall modes, so the bound is rounding.
  for (int n = 0; n < 4; ++n) {
    const Tensor G = channelG(height, fieldPoints[n], sources[n]);
    const double x[3] = {fieldPoints[n][0], height - fieldPoints[n][1], fieldPoints[n][2]};
    const double x0[3] = {sources[n][0], height - sources[n][1], sources[n][2]};
    const Tensor R = channelG(height, x, x0);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double sign = (i == 1) == (j == 1) ? 1.0 : -1.0;
        EXPECT_NEAR(R.g[i][j], sign * G.g[i][j], 1e-12 * maxAbs(G)) << n << " (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(ChannelStokeslet2P, DivergenceFree)
{
  // sum_i d_i G_ij = 0 by central differences, step 1e-4: truncation ~ 1e-8 |G'''| and rounding
  // ~ 1e-16 / 1e-4 of |G|, far below 1e-6 |G| / (distance to the source); a wrong factor a in
  // u_l = i w' / a leaves a divergence of order |G| / distance.
  const double step = 1e-4;
  for (int n = 0; n < 4; ++n) {
    const Tensor G = channelG(height, fieldPoints[n], sources[n]);
    for (int j = 0; j < 3; ++j) {
      double divergence = 0.0;
      for (int i = 0; i < 3; ++i) {
        double plus[3] = {fieldPoints[n][0], fieldPoints[n][1], fieldPoints[n][2]};
        double minus[3] = {plus[0], plus[1], plus[2]};
        plus[i] += step;
        minus[i] -= step;
        divergence +=
            (channelG(height, plus, sources[n]).g[i][j] - channelG(height, minus, sources[n]).g[i][j]) / (2.0 * step);
      }
      EXPECT_LT(std::fabs(divergence), 1e-6 * maxAbs(G)) << n << " force " << j;
    }
  }
}

TEST(ChannelStokeslet2P, ZeroModeIsTheCellAverage)
{
  // The average of G over a 24 x 24 grid of the cell at height y is the zero mode up to the
  // modes aliased onto it, |k| >= 2 pi 24 / L, of size e^{-2 pi 24 0.3 / 2} ~ 1e-10 (|y - h| >= 0.3).
  const double area = cell.lengthX * cell.lengthZ;
  const double x0[3] = {0.4, 0.45, 1.1};
  const int grid = 24;
  for (double y : {0.1, 0.8, 1.1}) {
    Tensor average{};
    for (int p = 0; p < grid; ++p) {
      for (int q = 0; q < grid; ++q) {
        const double x[3] = {(p + 0.3) * cell.lengthX / grid, y, (q + 0.7) * cell.lengthZ / grid};
        const Tensor G = channelG(height, x, x0);
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            average.g[i][j] += G.g[i][j] / (grid * grid);
          }
        }
      }
    }
    const double parallel = 8.0 * channelTestPi * std::min(y, x0[1]) * (height - std::max(y, x0[1])) / (height * area);
    EXPECT_NEAR(parallel, channelZeroModeProfile(y, x0[1], height) / area, 1e-15);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double expected = i == j && i != 1 ? parallel : 0.0;
        EXPECT_NEAR(average.g[i][j], expected, 1e-9) << "y " << y << " (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(ChannelStokeslet2P, TendsToTheLowerWallAsTheChannelWidens)
{
  // Near the lower wall G^C - G^W is the zero modes' difference, -8 pi y h / (H A) on the
  // parallel diagonal, plus the upper wall's modes k != 0, of size (a H)^2 e^{-a (2H - y - h)},
  // a = 2 pi / L_x: 1e-7 at H = 4 (measured 2.7e-8 of |G^W|), 1e-19 at H = 8, below rounding
  // (1e-12) beyond; the zero-mode difference itself (3e-3 |G^W| at H = 4) only halves with each
  // doubling of H, so leaving it out fails at every H.
  const double area = cell.lengthX * cell.lengthZ;
  const double x0[3] = {0.3, 0.6, 0.5};
  const double x[3] = {1.1, 0.25, 1.2};
  Tensor wall;
  periodicWallStokeslet2P(cell, ewaldTruncation(1.5, 1e-16), x, x0, wall.g);
  for (double H : {4.0, 8.0, 16.0}) {
    const Tensor G = channelG(H, x, x0);
    const double bound = (H == 4.0 ? 1e-7 : 1e-12) * maxAbs(wall);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double zeroModeShift = i == j && i != 1 ? -8.0 * channelTestPi * x[1] * x0[1] / (H * area) : 0.0;
        EXPECT_NEAR(G.g[i][j], wall.g[i][j] + zeroModeShift, bound) << "H " << H << " (" << i << ", " << j << ")";
      }
    }
  }
}

} // namespace channel_stokeslet_2p_test
