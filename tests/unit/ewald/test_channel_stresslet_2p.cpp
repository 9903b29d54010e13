// The reference series of the channel's stress (ChannelStresslet2P.hpp): the stress of the
// channel Stokeslet (ChannelStokeslet2P.hpp) by finite differences, momentum balance (which
// checks the pressure), periodicity, the reflection y -> H - y, the zero mode as the cell
// average, and the lower wall's periodic stress (WallStresslet2P.hpp) as the channel widens.
#include <capsula/ewald/ChannelStokeslet2P.hpp>
#include <capsula/ewald/ChannelStresslet2P.hpp>
#include <capsula/ewald/WallStresslet2P.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace channel_stresslet_2p_test {

using namespace capsula::ewald;
constexpr double stressTestPi = 3.14159265358979323846;

struct Stress {
  double t[3][3][3];
};

const PeriodicLayer stressCell{2.0, 1.5};
constexpr double stressHeight = 1.2;

Stress channelT(double H, const double x[3], const double x0[3])
{
  Stress s;
  periodicChannelStresslet2P(stressCell, H, x, x0, s.t);
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

const double stressSources[3][3] = {{0.3, 0.15, 0.2}, {1.1, 0.55, 0.9}, {1.9, 1.05, 0.1}};
const double stressPoints[3][3] = {{0.9, 0.45, 0.6}, {-0.4, 0.95, 0.3}, {1.6, 0.7, 1.2}};

TEST(ChannelStresslet2P, IsTheStressOfTheChannelStokeslet)
{
  // T + delta_ik P_j = d_k G_ij + d_i G_kj with P_j = -T_ljl / 3, the gradient of
  // periodicChannelStokeslet2P by central differences (step 1e-4: truncation ~1e-8, rounding
  // ~1e-12 of |G|); bound 1e-6 of |T|. A wrong derivative order of a profile is O(1).
  const double step = 1e-4;
  for (int n = 0; n < 3; ++n) {
    const Stress T = channelT(stressHeight, stressPoints[n], stressSources[n]);
    double grad[3][3][3]; // d_k G_ij
    for (int k = 0; k < 3; ++k) {
      double plus[3] = {stressPoints[n][0], stressPoints[n][1], stressPoints[n][2]};
      double minus[3] = {plus[0], plus[1], plus[2]};
      plus[k] += step;
      minus[k] -= step;
      double Gp[3][3], Gm[3][3];
      periodicChannelStokeslet2P(stressCell, stressHeight, plus, stressSources[n], Gp);
      periodicChannelStokeslet2P(stressCell, stressHeight, minus, stressSources[n], Gm);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          grad[i][j][k] = (Gp[i][j] - Gm[i][j]) / (2.0 * step);
        }
      }
    }
    for (int j = 0; j < 3; ++j) {
      const double pressure = -(T.t[0][j][0] + T.t[1][j][1] + T.t[2][j][2]) / 3.0;
      for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(T.t[i][j][k] + (i == k ? pressure : 0.0), grad[i][j][k] + grad[k][j][i], 1e-6 * maxAbs(T))
              << n << " (" << i << j << k << ")";
        }
      }
    }
  }
}

TEST(ChannelStresslet2P, MomentumBalance)
{
  // d_k T_ijk = -d_i P_j + lap G_ij = 0 off the source, by central differences of T (step
  // 1e-4: truncation ~1e-8, rounding ~1e-12 of |T| / step). This is the check of the
  // pressure (the previous test sees only its trace); bound 1e-5 of |T|, while a pressure
  // off by a factor or sign gives d_i P of order |T| / |x - x0|.
  const double step = 1e-4;
  for (int n = 0; n < 3; ++n) {
    const double scale = maxAbs(channelT(stressHeight, stressPoints[n], stressSources[n]));
    double divergence[3][3] = {};
    for (int k = 0; k < 3; ++k) {
      double plus[3] = {stressPoints[n][0], stressPoints[n][1], stressPoints[n][2]};
      double minus[3] = {plus[0], plus[1], plus[2]};
      plus[k] += step;
      minus[k] -= step;
      const Stress Tp = channelT(stressHeight, plus, stressSources[n]);
      const Stress Tm = channelT(stressHeight, minus, stressSources[n]);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          divergence[i][j] += (Tp.t[i][j][k] - Tm.t[i][j][k]) / (2.0 * step);
        }
      }
    }
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_LT(std::fabs(divergence[i][j]), 1e-5 * scale) << n << " (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(ChannelStresslet2P, PeriodicAndSymmetricUnderTheReflection)
{
  // A lattice shift: rounding of the phases (1e-12 relative). y -> H - y:
  // T_ijk(Rx, Rx0) = s_i s_j s_k T_ijk(x, x0), s = (1, -1, 1), with the pressure's constant
  // of zero mean (symmetric by construction); rounding, 1e-12 relative.
  for (int n = 0; n < 3; ++n) {
    const Stress T = channelT(stressHeight, stressPoints[n], stressSources[n]);
    const double moved[3] = {stressPoints[n][0] - stressCell.lengthX, stressPoints[n][1],
                             stressPoints[n][2] + 2.0 * stressCell.lengthZ};
    const double x[3] = {stressPoints[n][0], stressHeight - stressPoints[n][1], stressPoints[n][2]};
    const double x0[3] = {stressSources[n][0], stressHeight - stressSources[n][1], stressSources[n][2]};
    const Stress shifted = channelT(stressHeight, moved, stressSources[n]);
    const Stress reflected = channelT(stressHeight, x, x0);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          const double sign = ((i == 1) + (j == 1) + (k == 1)) % 2 == 0 ? 1.0 : -1.0;
          EXPECT_NEAR(shifted.t[i][j][k], T.t[i][j][k], 1e-12 * maxAbs(T));
          EXPECT_NEAR(reflected.t[i][j][k], sign * T.t[i][j][k], 1e-12 * maxAbs(T)) << n << " (" << i << j << k << ")";
        }
      }
    }
  }
}

TEST(ChannelStresslet2P, ZeroModeIsTheCellAverage)
{
  // The average over a 24 x 24 grid of the cell (aliased modes e^{-2 pi 24 0.3 / 2} ~ 1e-10):
  // the shear 8 pi (H - h) / (H A) below the force and -8 pi h / (H A) above on xxy, yxx, zzy,
  // yzz, minus the pressure 8 pi [step(y - h) - (H - h) / H] / A on xyx, yyy, zyz; bound 1e-9.
  const double area = stressCell.lengthX * stressCell.lengthZ;
  const double x0[3] = {0.4, 0.45, 1.1};
  const int grid = 24;
  for (double y : {0.1, 0.8, 1.1}) {
    Stress average{};
    for (int p = 0; p < grid; ++p) {
      for (int q = 0; q < grid; ++q) {
        const double x[3] = {(p + 0.3) * stressCell.lengthX / grid, y, (q + 0.7) * stressCell.lengthZ / grid};
        const Stress T = channelT(stressHeight, x, x0);
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            for (int k = 0; k < 3; ++k) {
              average.t[i][j][k] += T.t[i][j][k] / (grid * grid);
            }
          }
        }
      }
    }
    const double h = x0[1];
    const double shear = 8.0 * stressTestPi * (y < h ? (stressHeight - h) : -h) / (stressHeight * area);
    const double pressure = 8.0 * stressTestPi * ((y > h ? 1.0 : 0.0) - (stressHeight - h) / stressHeight) / area;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          double expected = 0.0;
          if (j != 1 && ((i == j && k == 1) || (i == 1 && k == j))) {
            expected += shear;
          }
          if (j == 1 && i == k) {
            expected -= pressure;
          }
          EXPECT_NEAR(average.t[i][j][k], expected, 1e-9) << "y " << y << " (" << i << j << k << ")";
        }
      }
    }
  }
}

TEST(ChannelStresslet2P, TendsToTheLowerWallAsTheChannelWidens)
{
  // Near the lower wall T^C - T^W is the zero modes' difference, -8 pi h / (H A) on xxy, yxx,
  // zzy, yzz (the shear of -8 pi y h / (H A)) and on xyx, yyy, zyz (the pressure constant
  // 8 pi h / (H A) above the wall's), plus the upper wall's modes, ~(a H)^2 e^{-a (2H - y - h)}
  // with a = pi: 1e-19 at H = 8; bound 1e-10 of |T^W| (the shift itself is 6e-3 of it at H = 8).
  const double area = stressCell.lengthX * stressCell.lengthZ;
  const double x0[3] = {0.3, 0.6, 0.5};
  const double x[3] = {1.1, 0.25, 1.2};
  double wall[3][3][3];
  periodicWallStresslet2P(stressCell, ewaldTruncation(1.5, 1e-16), x, x0, wall);
  double scale = 0.0;
  for (const auto& plane : wall) {
    for (const auto& row : plane) {
      for (double v : row) {
        scale = std::max(scale, std::fabs(v));
      }
    }
  }
  for (double H : {8.0, 16.0}) {
    const Stress T = channelT(H, x, x0);
    const double shift = -8.0 * stressTestPi * x0[1] / (H * area);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          const bool shear = j != 1 && ((i == j && k == 1) || (i == 1 && k == j));
          const bool pressure = j == 1 && i == k;
          EXPECT_NEAR(T.t[i][j][k], wall[i][j][k] + (shear || pressure ? shift : 0.0), 1e-10 * scale)
              << "H " << H << " (" << i << j << k << ")";
        }
      }
    }
  }
}

} // namespace channel_stresslet_2p_test
