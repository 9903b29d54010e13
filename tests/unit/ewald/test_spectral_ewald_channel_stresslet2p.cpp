// The fast double layer of the channel's stresslet (SpectralEwaldChannelStresslet2P.hpp)
// against the reference series of the channel's stress (ChannelStresslet2P.hpp) for
// tolerances 1e-3 to 1e-8, no slip on both walls, and the reflection y -> H - y.
#include <capsula/ewald/ChannelStresslet2P.hpp>
#include <capsula/ewald/SpectralEwaldChannelStresslet2P.hpp>

#include "EwaldTesting.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <utility>
#include <vector>

namespace spectral_ewald_channel_stresslet_2p_test {

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

TEST(SpectralEwaldChannelStresslet2P, AgreesWithTheReferenceWithinTheTolerance)
{
  // 24 sources in three bands (near each wall and across the split y = H/2), 12 targets at
  // heights 0.375 and 0.825, at least 0.1 from every source (the reference series needs
  // |y - h| away from 0, and poles inside the channel). Random tensors, not traceless: the zero
  // mode of u_y is then the reference's pressure convention. Bound: the tolerance (relative to
  // the largest velocity), as for the channel's Stokeslet.
  const auto sources = pointsInBands({{0.1, 0.25}, {0.5, 0.7}, {0.95, 1.1}}, 8, 31);
  const auto tensors = randomForces(24, 32, 9);
  const auto targets = pointsInBands({{0.375, 0.375}, {0.825, 0.825}}, 6, 33);
  const auto reference = capsula::ewald::testing::doubleLayerSum(
      sources, tensors, targets, [](const double* x, const double* x0, double T[3][3][3]) {
        periodicChannelStresslet2P(channelBox, channelHeight, x, x0, T);
      });
  for (double tolerance : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
    const auto fast = spectralEwaldChannelStresslet2P(channelBox, channelHeight, tolerance, sources, tensors, targets);
    const double error = relativeError(fast, reference);
    std::printf("channel stresslet tolerance %.0e: error %.2e\n", tolerance, error);
    EXPECT_LT(error, tolerance) << "tolerance " << tolerance;
  }
}

TEST(SpectralEwaldChannelStresslet2P, NoSlipOnBothWallsToTheTolerance)
{
  const auto sources = randomPoints(channelBox, 40, 41, 0.05, channelHeight - 0.05);
  const auto tensors = randomForces(40, 42, 9);
  auto onWalls = randomPoints(channelBox, 20, 43, 0.0, 0.0);
  const auto onUpperWall = randomPoints(channelBox, 20, 44, channelHeight, channelHeight);
  onWalls.insert(onWalls.end(), onUpperWall.begin(), onUpperWall.end());
  const auto inside = randomPoints(channelBox, 40, 45, 0.1, channelHeight - 0.1);
  const double scale =
      largestSpeed(spectralEwaldChannelStresslet2P(channelBox, channelHeight, 1e-6, sources, tensors, inside));
  for (double tolerance : {1e-3, 1e-6, 1e-8}) {
    const double slip =
        largestSpeed(spectralEwaldChannelStresslet2P(channelBox, channelHeight, tolerance, sources, tensors, onWalls));
    std::printf("channel stresslet tolerance %.0e: slip %.2e\n", tolerance, slip / scale);
    EXPECT_LT(slip, tolerance * scale) << "tolerance " << tolerance;
  }
}

TEST(SpectralEwaldChannelStresslet2P, SymmetricUnderTheReflectionAcrossTheMidplane)
{
  // y -> H - y for points, s_i s_k S_ik for tensors and y components flipped for velocities
  // swaps the two groups; the flows agree to the two evaluations' errors, 2 tol.
  const auto sources = randomPoints(channelBox, 30, 61, 0.05, channelHeight - 0.05);
  const auto tensors = randomForces(30, 62, 9);
  const auto targets = randomPoints(channelBox, 30, 63, 0.0, channelHeight);
  auto reflect = [](std::vector<double> v, double shift) {
    for (std::size_t n = 1; n < v.size(); n += 3) {
      v[n] = shift - v[n];
    }
    return v;
  };
  auto reflectTensors = tensors;
  for (std::size_t n = 0; n < reflectTensors.size(); n += 9) {
    for (int entry : {1, 3, 5, 7}) {
      reflectTensors[n + entry] = -reflectTensors[n + entry];
    }
  }
  const double tolerance = 1e-7;
  const auto u = spectralEwaldChannelStresslet2P(channelBox, channelHeight, tolerance, sources, tensors, targets);
  const auto mirrored =
      reflect(spectralEwaldChannelStresslet2P(channelBox, channelHeight, tolerance, reflect(sources, channelHeight),
                                              reflectTensors, reflect(targets, channelHeight)),
              0.0);
  EXPECT_LT(relativeError(mirrored, u), 2.0 * tolerance);
}

} // namespace spectral_ewald_channel_stresslet_2p_test
