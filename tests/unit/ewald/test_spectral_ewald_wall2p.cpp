// The spectral Ewald fast sum of the lower wall's Stokeslet (SpectralEwaldWall2P.hpp) against
// its reference sum (WallStokeslet2P.hpp): within the tolerance from 1e-3 to 1e-8, and no slip
// on the wall to the tolerance.
#include <capsula/ewald/SpectralEwaldWall2P.hpp>
#include <capsula/ewald/WallStokeslet2P.hpp>

#include "EwaldTesting.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace spectral_ewald_wall_2p_test {

using namespace capsula::ewald;
using capsula::ewald::testing::largestSpeed;
using capsula::ewald::testing::randomForces;
using capsula::ewald::testing::randomPoints;
using capsula::ewald::testing::relativeError;

const PeriodicLayer wallBox{2.0, 1.6};

/// sum_n G^W(x_t, x_n) g_n by the reference sum (to 1e-15).
std::vector<double> wallReferenceSum(const std::vector<double>& sources, const std::vector<double>& forces,
                                     const std::vector<double>& targets)
{
  const EwaldTruncation truncation = ewaldTruncation(2.0, 1e-15);
  return capsula::ewald::testing::pairSum(sources, forces, targets,
                                          [&](const double* x, const double* x0, double G[3][3]) {
                                            periodicWallStokeslet2P(wallBox, truncation, x, x0, G);
                                          });
}

TEST(SpectralEwaldWall2P, AgreesWithTheReferenceWithinTheTolerance)
{
  // 40 sources at heights 0.05..1, 30 targets at 0..1.3. The error bound is the tolerance
  // itself (relative to the largest velocity); measured 0.10-0.15 tol.
  const auto sources = randomPoints(wallBox, 40, 11, 0.05, 1.0);
  const auto forces = randomForces(40, 12);
  const auto targets = randomPoints(wallBox, 30, 13, 0.0, 1.3);
  const auto reference = wallReferenceSum(sources, forces, targets);
  for (double tolerance : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
    const auto fast = spectralEwaldWall2P(wallBox, tolerance, sources, forces, targets);
    const double error = relativeError(fast, reference);
    std::printf("wall tolerance %.0e: error %.2e\n", tolerance, error);
    EXPECT_LT(error, tolerance) << "tolerance " << tolerance;
  }
}

TEST(SpectralEwaldWall2P, NoSlipToTheTolerance)
{
  // Targets on y = 0: the reference gives zero to rounding, the fast sum to its tolerance (of
  // the largest velocity above the wall); measured 7e-6, 3e-8, 1e-9 at tol = 1e-3, 1e-6, 1e-8.
  const auto sources = randomPoints(wallBox, 40, 21, 0.05, 1.0);
  const auto forces = randomForces(40, 22);
  auto onWall = randomPoints(wallBox, 20, 23, 0.0, 0.0);
  const auto above = randomPoints(wallBox, 20, 24, 0.2, 1.0);
  const double scale = largestSpeed(spectralEwaldWall2P(wallBox, 1e-6, sources, forces, above));
  for (double tolerance : {1e-3, 1e-6, 1e-8}) {
    const double slip = largestSpeed(spectralEwaldWall2P(wallBox, tolerance, sources, forces, onWall));
    std::printf("wall tolerance %.0e: slip %.2e\n", tolerance, slip / scale);
    EXPECT_LT(slip, tolerance * scale) << "tolerance " << tolerance;
  }
}

} // namespace spectral_ewald_wall_2p_test
