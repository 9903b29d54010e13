// The fast double layer of the lower wall's stresslet (SpectralEwaldWallStresslet2P.hpp)
// against the reference sum of the wall's stress (WallStresslet2P.hpp) for tolerances 1e-3 to
// 1e-8, and no slip on the wall.
#include <capsula/ewald/SpectralEwaldWallStresslet2P.hpp>
#include <capsula/ewald/WallStresslet2P.hpp>

#include "EwaldTesting.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

namespace spectral_ewald_wall_stresslet_2p_test {

using namespace capsula::ewald;
using capsula::ewald::testing::largestSpeed;
using capsula::ewald::testing::randomForces;
using capsula::ewald::testing::randomPoints;
using capsula::ewald::testing::relativeError;

const PeriodicLayer wallBox{2.0, 1.6};

/// sum_n T^W_ijk(x_n, x_t) S_n,ik by the reference sum (to 1e-15).
std::vector<double> wallDoubleLayerReference(const std::vector<double>& sources, const std::vector<double>& tensors,
                                             const std::vector<double>& targets)
{
  const EwaldTruncation truncation = ewaldTruncation(2.0, 1e-15);
  return capsula::ewald::testing::doubleLayerSum(sources, tensors, targets,
                                                 [&](const double* x, const double* x0, double T[3][3][3]) {
                                                   periodicWallStresslet2P(wallBox, truncation, x, x0, T);
                                                 });
}

TEST(SpectralEwaldWallStresslet2P, AgreesWithTheReferenceWithinTheTolerance)
{
  // 40 sources at heights 0.05..1 with random (not symmetric, not traceless) tensors, 30
  // targets at 0..1.3. The bound is the tolerance (relative to the largest velocity); a sign
  // or a factor wrong in any of the five image terms errs by O(1).
  const auto sources = randomPoints(wallBox, 40, 11, 0.05, 1.0);
  const auto tensors = randomForces(40, 12, 9);
  const auto targets = randomPoints(wallBox, 30, 13, 0.0, 1.3);
  const auto reference = wallDoubleLayerReference(sources, tensors, targets);
  for (double tolerance : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
    const auto fast = spectralEwaldWallStresslet2P(wallBox, tolerance, sources, tensors, targets);
    const double error = relativeError(fast, reference);
    std::printf("wall stresslet tolerance %.0e: error %.2e\n", tolerance, error);
    EXPECT_LT(error, tolerance) << "tolerance " << tolerance;
  }
}

TEST(SpectralEwaldWallStresslet2P, NoSlipToTheTolerance)
{
  // Targets on y = 0: the stresslet at the targets and at their reflections cancel, the
  // Laplace terms carry the factor y_t = 0; what remains is the sums' error, below the
  // tolerance of the largest velocity above the wall.
  const auto sources = randomPoints(wallBox, 40, 21, 0.05, 1.0);
  const auto tensors = randomForces(40, 22, 9);
  const auto onWall = randomPoints(wallBox, 20, 23, 0.0, 0.0);
  const auto above = randomPoints(wallBox, 20, 24, 0.2, 1.0);
  const double scale = largestSpeed(spectralEwaldWallStresslet2P(wallBox, 1e-6, sources, tensors, above));
  for (double tolerance : {1e-3, 1e-6, 1e-8}) {
    const double slip = largestSpeed(spectralEwaldWallStresslet2P(wallBox, tolerance, sources, tensors, onWall));
    std::printf("wall stresslet tolerance %.0e: slip %.2e\n", tolerance, slip / scale);
    EXPECT_LT(slip, tolerance * scale) << "tolerance " << tolerance;
  }
}

} // namespace spectral_ewald_wall_stresslet_2p_test
