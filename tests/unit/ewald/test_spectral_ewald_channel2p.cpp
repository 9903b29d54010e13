// The fast sum of the channel Stokeslet (SpectralEwaldChannel2P.hpp) against its reference
// series (ChannelStokeslet2P.hpp) for tolerances 1e-3 to 1e-8; no slip on both walls, the zero
// mode as the cell average, the reflection y -> H - y, and the lower wall's fast sum
// (SpectralEwaldWall2P.hpp) as the channel widens.
#include <capsula/ewald/ChannelStokeslet2P.hpp>
#include <capsula/ewald/SpectralEwaldChannel2P.hpp>
#include <capsula/ewald/SpectralEwaldWall2P.hpp>

#include "EwaldTesting.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace spectral_ewald_channel_2p_test {

using namespace capsula::ewald;
using capsula::ewald::testing::largestSpeed;
using capsula::ewald::testing::randomForces;
using capsula::ewald::testing::randomPoints;
using capsula::ewald::testing::relativeError;

const PeriodicLayer channelBox{2.0, 1.6};
constexpr double channelHeight = 1.2;

/// Points in bands of heights in the channel's box (EwaldTesting.hpp).
std::vector<double> pointsInBands(const std::vector<std::pair<double, double>>& bands, int count, unsigned seed)
{
  return capsula::ewald::testing::pointsInBands(channelBox, bands, count, seed);
}

/// Sources in three bands, on both sides of the split y = H/2 = 0.6 and near both walls; the
/// reference targets at heights 0, 0.375, 0.825 and H, at least 0.1 from every source height
/// (the reference series needs |y - h| away from 0).
const std::vector<std::pair<double, double>> sourceBands{{0.1, 0.25}, {0.5, 0.7}, {0.95, 1.1}};
const std::vector<std::pair<double, double>> targetHeights{
    {0.0, 0.0}, {0.375, 0.375}, {0.825, 0.825}, {channelHeight, channelHeight}};

/// sum_n G^C(x_t, x_n) g_n by the reference series (to 1e-15).
std::vector<double> channelReferenceSum(const std::vector<double>& sources, const std::vector<double>& forces,
                                        const std::vector<double>& targets)
{
  return capsula::ewald::testing::pairSum(sources, forces, targets,
                                          [](const double* x, const double* x0, double G[3][3]) {
                                            periodicChannelStokeslet2P(channelBox, channelHeight, x, x0, G);
                                          });
}

TEST(SpectralEwaldChannel2P, AgreesWithTheReferenceWithinTheTolerance)
{
  // 24 sources, 24 targets (6 per height, two heights on the walls). The bound is the tolerance
  // (relative to the largest velocity): the lower wall's sums are within it, and the far-wall
  // correction adds their error on the far-wall grid (carried into the slab with a gain below 1)
  // and the modes beyond k_c (below tol by the cutoff rule).
  const auto sources = pointsInBands(sourceBands, 8, 31);
  const auto forces = randomForces(24, 32);
  const auto targets = pointsInBands(targetHeights, 6, 33);
  const auto reference = channelReferenceSum(sources, forces, targets);
  for (double tolerance : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
    const auto fast = spectralEwaldChannel2P(channelBox, channelHeight, tolerance, sources, forces, targets);
    const double error = relativeError(fast, reference);
    std::printf("channel tolerance %.0e: error %.2e\n", tolerance, error);
    EXPECT_LT(error, tolerance) << "tolerance " << tolerance;
  }
}

TEST(SpectralEwaldChannel2P, NoSlipOnBothWallsToTheTolerance)
{
  // Targets on y = 0 and y = H: each group's own wall has no slip to its sum's tolerance, and
  // its far wall to the tolerance of the sampled data and the modes kept.
  const auto sources = randomPoints(channelBox, 40, 41, 0.05, channelHeight - 0.05);
  const auto forces = randomForces(40, 42);
  auto onWalls = randomPoints(channelBox, 20, 43, 0.0, 0.0);
  const auto onUpperWall = randomPoints(channelBox, 20, 44, channelHeight, channelHeight);
  onWalls.insert(onWalls.end(), onUpperWall.begin(), onUpperWall.end());
  const auto inside = randomPoints(channelBox, 40, 45, 0.1, channelHeight - 0.1);
  const double scale = largestSpeed(spectralEwaldChannel2P(channelBox, channelHeight, 1e-6, sources, forces, inside));
  for (double tolerance : {1e-3, 1e-6, 1e-8}) {
    const double slip =
        largestSpeed(spectralEwaldChannel2P(channelBox, channelHeight, tolerance, sources, forces, onWalls));
    std::printf("channel tolerance %.0e: slip %.2e\n", tolerance, slip / scale);
    EXPECT_LT(slip, tolerance * scale) << "tolerance " << tolerance;
  }
}

TEST(SpectralEwaldChannel2P, ZeroModeIsTheCellAverage)
{
  // The average over a 64 x 64 grid of the cell at heights 0.375 and 0.825 is the zero mode
  // sum_n 8 pi min(y, h_n) (H - max(y, h_n)) g_n,parallel / (H A) (no mean normal flow), up to
  // the aliased modes (e^{-2 pi 64 0.125 / 2} ~ 1e-11) and the tolerance 1e-8 of the largest
  // velocity. Each group's far-wall correction carries the mode: without it the average would
  // be the lower wall's, 8 pi min(y, h) / A, off by O(1).
  const auto sources = pointsInBands(sourceBands, 8, 51);
  const auto forces = randomForces(24, 52);
  const double area = channelBox.lengthX * channelBox.lengthZ;
  const int grid = 64;
  for (double y : {0.375, 0.825}) {
    std::vector<double> targets;
    for (int p = 0; p < grid; ++p) {
      for (int q = 0; q < grid; ++q) {
        const double x[3] = {(p + 0.5) * channelBox.lengthX / grid, y, (q + 0.25) * channelBox.lengthZ / grid};
        targets.insert(targets.end(), x, x + 3);
      }
    }
    const auto u = spectralEwaldChannel2P(channelBox, channelHeight, 1e-8, sources, forces, targets);
    double average[3] = {0.0, 0.0, 0.0}, expected[3] = {0.0, 0.0, 0.0};
    for (std::size_t t = 0; t < u.size(); t += 3) {
      for (int i = 0; i < 3; ++i) {
        average[i] += u[t + i] / (grid * grid);
      }
    }
    for (std::size_t n = 0; n < sources.size(); n += 3) {
      const double profile = channelZeroModeProfile(y, sources[n + 1], channelHeight) / area;
      expected[0] += profile * forces[n];
      expected[2] += profile * forces[n + 2];
    }
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(average[i], expected[i], 1e-8 * largestSpeed(u)) << "y " << y << " component " << i;
    }
  }
}

TEST(SpectralEwaldChannel2P, SymmetricUnderTheReflectionAcrossTheMidplane)
{
  // Reflecting sources, forces and targets (y -> H - y, y components flipped) swaps the two
  // groups; the flows agree up to the two evaluations' errors, 2 tol of the largest velocity.
  const auto sources = randomPoints(channelBox, 30, 61, 0.05, channelHeight - 0.05);
  const auto forces = randomForces(30, 62);
  const auto targets = randomPoints(channelBox, 30, 63, 0.0, channelHeight);
  auto reflect = [](std::vector<double> v, double shift) {
    for (std::size_t n = 1; n < v.size(); n += 3) {
      v[n] = shift - v[n];
    }
    return v;
  };
  const double tolerance = 1e-7;
  const auto u = spectralEwaldChannel2P(channelBox, channelHeight, tolerance, sources, forces, targets);
  const auto mirrored =
      reflect(spectralEwaldChannel2P(channelBox, channelHeight, tolerance, reflect(sources, channelHeight),
                                     reflect(forces, 0.0), reflect(targets, channelHeight)),
              0.0);
  EXPECT_LT(relativeError(mirrored, u), 2.0 * tolerance);
}

TEST(SpectralEwaldChannel2P, TendsToTheLowerWallsFastSumAsTheChannelWidens)
{
  // Sources and targets near the lower wall of a channel H = 20: the upper wall's modes k != 0
  // are e^{-2 pi 2H / L} ~ 1e-54 small, so the channel's flow is the lower wall's plus the
  // zero modes' difference -8 pi y h g_parallel / (H A), to the two fast sums' tolerances.
  const double H = 20.0;
  const auto sources = randomPoints(channelBox, 30, 71, 0.05, 1.0);
  const auto forces = randomForces(30, 72);
  const auto targets = randomPoints(channelBox, 30, 73, 0.0, 1.3);
  const double tolerance = 1e-7;
  auto expected = spectralEwaldWall2P(channelBox, tolerance, sources, forces, targets);
  const double area = channelBox.lengthX * channelBox.lengthZ;
  constexpr double pi = 3.14159265358979323846;
  for (std::size_t t = 0; t < targets.size(); t += 3) {
    for (std::size_t n = 0; n < sources.size(); n += 3) {
      const double shift = -8.0 * pi * targets[t + 1] * sources[n + 1] / (H * area);
      expected[t] += shift * forces[n];
      expected[t + 2] += shift * forces[n + 2];
    }
  }
  const auto u = spectralEwaldChannel2P(channelBox, H, tolerance, sources, forces, targets);
  EXPECT_LT(relativeError(u, expected), 2.0 * tolerance);
}

TEST(SpectralEwaldChannel2P, TargetOnASourceGetsTheRegularPart)
{
  // A target on a source takes lim (G^C - G_free) g_n from that source (the lower wall's
  // convention, in either frame). The limit from the reference: R(d) = G^C(x_n + d e_y, x_n)
  // - G_free(d e_y), smooth in d, its even part extrapolated to d = 0 from d = +-0.025 and
  // +-0.05 (Richardson, error ~ d^4 |R^(4)|: measured 0.7-4e-6 of |R g|, 16 times more at twice
  // the steps); the fast sum at tol 1e-10 on top. Bound 1e-5 of |R g|, while dropping the
  // images or keeping a part of the free Stokeslet's limit errs by O(|R g|).
  const auto sources = randomPoints(channelBox, 4, 91, 0.3, 0.9);
  const auto forces = randomForces(4, 92);
  for (std::size_t n = 0; n < sources.size(); n += 3) {
    const std::vector<double> source(sources.begin() + n, sources.begin() + n + 3);
    const std::vector<double> force(forces.begin() + n, forces.begin() + n + 3);
    const auto fast = spectralEwaldChannel2P(channelBox, channelHeight, 1e-10, source, force, source);
    auto regular = [&](double d) {
      const double x[3] = {source[0], source[1] + d, source[2]};
      double G[3][3];
      periodicChannelStokeslet2P(channelBox, channelHeight, x, source.data(), G);
      G[0][0] -= 1.0 / std::fabs(d); // G_free = delta_ij / r + x_i x_j / r^3 at x = d e_y
      G[1][1] -= 2.0 / std::fabs(d);
      G[2][2] -= 1.0 / std::fabs(d);
      std::vector<double> u(3, 0.0);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          u[i] += G[i][j] * force[j];
        }
      }
      return u;
    };
    const auto near1 = regular(0.025), near2 = regular(-0.025), far1 = regular(0.05), far2 = regular(-0.05);
    std::vector<double> limit(3);
    for (int i = 0; i < 3; ++i) {
      limit[i] = (4.0 * 0.5 * (near1[i] + near2[i]) - 0.5 * (far1[i] + far2[i])) / 3.0;
    }
    const double error = relativeError(fast, limit);
    std::printf("channel target on source %zu: error %.2e\n", n / 3, error);
    EXPECT_LT(error, 1e-5) << "source " << n / 3;
  }
}

TEST(SpectralEwaldChannel2P, PeriodicInXAndZ)
{
  // Targets moved by lattice vectors land on the same grid nodes (indices wrapped) with the
  // same window weights up to the rounding of x / h: the flows agree to 1e-12 of the largest.
  const auto sources = randomPoints(channelBox, 30, 81, 0.05, channelHeight - 0.05);
  const auto forces = randomForces(30, 82);
  const auto targets = randomPoints(channelBox, 30, 83, 0.0, channelHeight);
  auto moved = targets;
  for (std::size_t t = 0; t < moved.size(); t += 3) {
    moved[t] += 3.0 * channelBox.lengthX;
    moved[t + 2] -= 2.0 * channelBox.lengthZ;
  }
  const auto u = spectralEwaldChannel2P(channelBox, channelHeight, 1e-6, sources, forces, targets);
  const auto v = spectralEwaldChannel2P(channelBox, channelHeight, 1e-6, sources, forces, moved);
  EXPECT_LT(relativeError(v, u), 1e-12);
}

TEST(SpectralEwaldChannel2P, RefusesPointsOutsideTheChannel)
{
  // Sources on or beyond a wall, and targets outside [0, H], have no channel flow; a channel
  // without height or a tolerance outside (0, 1) has no sum.
  const std::vector<double> inside{0.5, 0.6, 0.5}, force{1.0, 0.0, 0.0};
  for (double h : {0.0, channelHeight, -0.1, 1.3}) {
    const std::vector<double> source{0.5, h, 0.5};
    EXPECT_THROW(spectralEwaldChannel2P(channelBox, channelHeight, 1e-6, source, force, inside), std::invalid_argument)
        << "source height " << h;
  }
  for (double y : {-1e-9, channelHeight + 1e-9}) {
    const std::vector<double> target{0.5, y, 0.5};
    EXPECT_THROW(spectralEwaldChannel2P(channelBox, channelHeight, 1e-6, inside, force, target), std::invalid_argument)
        << "target height " << y;
  }
  EXPECT_THROW(spectralEwaldChannel2P(channelBox, 0.0, 1e-6, inside, force, inside), std::invalid_argument);
  for (double tolerance : {0.0, 1.0}) { // before the far-wall grid is sized from ln(1/tol)
    EXPECT_THROW(spectralEwaldChannel2P(channelBox, channelHeight, tolerance, inside, force, inside),
                 std::invalid_argument)
        << "tolerance " << tolerance;
  }
}

// Faxen's wall corrections for a sphere moving parallel to two plane walls (Happel & Brenner,
// Low Reynolds Number Hydrodynamics, 1965, Sec. 7-4): the mobility is
// 1 - c a / l + O((a / l)^3), l the distance to the nearer wall, c = 1.004 on the mid-plane and
// 0.6526 on the quarter-plane (where the lower wall alone gives Lorentz's 9 / 16). The term in
// a / l is the first reflection, the regular part of the channel's Stokeslet at its pole:
// (G^C - G_free)_xx (x0, x0) = -8 pi c / (6 pi l), which the fast sum gives for a target on its
// source. In a periodic box the images and the zero mode add O((H / L)^2) (measured: the
// differences between L = 8 and 16 are four times those between 16 and 32), so the value is
// extrapolated from L = 8 and 16 (Richardson in L^-2): c = 1.00412 and 0.65263. The
// coefficients are quoted to 4 digits; 1e-3 and 3e-4 allow for that. Without the
// extrapolation (L = 16) they are 1.0007 and 0.6517; a lost wall or zero mode, or a wrong
// reflection, misses by far more.
TEST(SpectralEwaldChannel2P, ReproducesFaxensWallCorrectionsMidwayAndAtTheQuarterPlane)
{
  constexpr double pi = 3.14159265358979323846;
  const double height = 1.0;
  const auto regularPart = [&](double length, double h) {
    const PeriodicLayer layer{length, length};
    const std::vector<double> source = {0.3 * length, h, 0.4 * length}, force = {1.0, 0.0, 0.0};
    return spectralEwaldChannel2P(layer, height, 1e-9, source, force, source)[0];
  };
  for (const auto& [h, faxen, allowed] : {std::tuple{0.5, 1.004, 1e-3}, std::tuple{0.25, 0.6526, 3e-4}}) {
    const double extrapolated = (4.0 * regularPart(16.0, h) - regularPart(8.0, h)) / 3.0;
    const double l = std::min(h, height - h);
    const double coefficient = -extrapolated * 6.0 * pi * l / (8.0 * pi);
    std::printf("Faxen's coefficient at l / H = %.2f: %.5f (published %.4f)\n", l / height, coefficient, faxen);
    EXPECT_NEAR(coefficient, faxen, allowed);
  }
}

} // namespace spectral_ewald_channel_2p_test
