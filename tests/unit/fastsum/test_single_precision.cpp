// The treecode's single-precision single layer: the float Stokeslet terms against the
// double ones (operators/ContractedKernels.hpp), in coordinates taken from a shifted
// origin; the sums in float against the direct double sums; the double layer left in
// double; and the precision the tolerance table picks.
#include "FastsumTesting.hpp"

#include <capsula/fastsum/SinglePrecisionKernels.hpp>
#include <capsula/fastsum/Treecode.hpp>
#include <capsula/operators/ContractedKernels.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace testsets = capsula::fastsum::testsets;
using capsula::fastsum::SinglePrecisionKernel;
using capsula::fastsum::Treecode;
using capsula::fastsum::TreecodeParameters;
using capsula::fastsum::treecodeParametersForTolerance;
using capsula::operators::FreeSpace3DKernel;
using capsula::operators::Wall3DKernel;

namespace {

double norm(const double u[3])
{
  return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
}

// The largest difference of the float terms from the double ones at random pairs above the
// wall, the float coordinates relative to an origin o near the pole.
template <class Kernel>
void expectFloatTermsMatch()
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> across(-3.0, 3.0), up(0.05, 3.0), unit(-1.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const double x[3] = {across(random), up(random), across(random)};
    const double x0[3] = {across(random), up(random), across(random)};
    const double o[3] = {x0[0] + 0.1 * unit(random), x0[1] + 0.1 * unit(random), x0[2] + 0.1 * unit(random)};
    const double f[3] = {unit(random), unit(random), unit(random)};
    double u[3] = {0.0, 0.0, 0.0};
    Kernel::addSingleLayerTerm(x, x0, f, u);
    float xs[3], x0s[3], fs[3];
    for (int i = 0; i < 3; ++i) {
      xs[i] = static_cast<float>(x[i] - o[i]);
      x0s[i] = static_cast<float>(x0[i] - o[i]);
      fs[i] = static_cast<float>(f[i]);
    }
    const float H = static_cast<float>(o[capsula::greens::wallNormalAxis]);
    float us[3] = {0.0f, 0.0f, 0.0f};
    SinglePrecisionKernel<Kernel>::addSingleLayerTerm(xs, x0s, H, fs, us);
    double error[3];
    for (int j = 0; j < 3; ++j) {
      error[j] = static_cast<double>(us[j]) - u[j];
    }
    // Relative to the size of the free-space term, |f| / r: near the wall the image
    // cancels most of the pole's term.
    const double d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    worst = std::max(worst, norm(error) * norm(d) / norm(f));
  }
  std::printf("  %s: float terms off by at most %.1e\n", Kernel::name, worst);
  // A wrong sign or factor in any part is an O(1) difference; round-off is a few 1e-7.
  EXPECT_LT(worst, 1e-5);
}

using testsets::LayerErrors;
using testsets::treecodeErrors;

} // namespace

TEST(SinglePrecision, FreeSpaceTermsMatchTheDoubleOnes)
{
  expectFloatTermsMatch<FreeSpace3DKernel>();
}

TEST(SinglePrecision, WallTermsMatchTheDoubleOnes)
{
  expectFloatTermsMatch<Wall3DKernel>();
}

TEST(SinglePrecision, EveryPairInFloatIsTheDirectSumToRoundOff)
{
  // theta = 0: every interaction direct, the single layer in float, the double layer in
  // double (so the tree's order only). Two level-3 spheres 0.1 above the wall; measured
  // 4.6e-8 (free space) and 1.3e-7 (wall).
  const auto s = testsets::spheresNearWall(2, 3, 1.1, 9);
  TreecodeParameters parameters;
  parameters.theta = 0.0;
  parameters.singlePrecision = true;
  for (const LayerErrors& e :
       {treecodeErrors<FreeSpace3DKernel>(s, parameters), treecodeErrors<Wall3DKernel>(s, parameters)}) {
    std::printf("  all pairs in float: single %.2e, double %.2e\n", e.single, e.dbl);
    EXPECT_LT(e.single, 1e-6);
    EXPECT_LT(e.dbl, 1e-13);
  }
}

TEST(SinglePrecision, FloatProxiesAtAHighDegreeAreTheDirectSum)
{
  // Degree 9 at theta = 0.5: the interpolation error is of the order of the float
  // round-off (measured ~3e-8), which a wrong term would exceed by orders.
  const auto s = testsets::randomCloud(20000, 1500, 23);
  TreecodeParameters parameters;
  parameters.degree = 9;
  parameters.theta = 0.5;
  parameters.singlePrecision = true;
  for (const LayerErrors& e :
       {treecodeErrors<FreeSpace3DKernel>(s, parameters), treecodeErrors<Wall3DKernel>(s, parameters)}) {
    std::printf("  float proxies, degree 9: single %.2e, double %.2e\n", e.single, e.dbl);
    EXPECT_LT(e.single, 1e-6);
    EXPECT_LT(e.dbl, 1e-6);
  }
}

TEST(SinglePrecision, TheWallKernelVanishesForPolesOnTheWall)
{
  // Blake's image cancels its pole exactly for a pole on the wall (no-slip); in float too,
  // with the pole among targets above the wall in one block.
  auto s = testsets::randomCloud(3000, 200, 31);
  for (int t = 0; t < s.numTargets(); t += 3) {
    s.targets[3 * t + capsula::greens::wallNormalAxis] = 0.0;
  }
  TreecodeParameters parameters;
  parameters.singlePrecision = true;
  parameters.theta = 0.0;
  Treecode<Wall3DKernel> treecode(parameters);
  treecode.setSources(s.x.data(), s.y.data(), s.z.data(), s.numSources());
  treecode.setTargets(s.targets.data(), s.numTargets());
  std::vector<double> u(3 * static_cast<std::size_t>(s.numTargets()));
  treecode.singleLayer(s.fx.data(), s.fy.data(), s.fz.data(), u.data());
  for (int t = 0; t < s.numTargets(); ++t) {
    if (t % 3 == 0) {
      EXPECT_EQ(u[3 * t], 0.0);
      EXPECT_EQ(u[3 * t + 1], 0.0);
      EXPECT_EQ(u[3 * t + 2], 0.0);
    } else {
      EXPECT_NE(u[3 * t], 0.0);
    }
  }
}

TEST(SinglePrecision, TheTablePicksFloatOnlyWhereItWasMeasuredToFit)
{
  for (const double tolerance : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    EXPECT_TRUE(treecodeParametersForTolerance(tolerance).singlePrecision) << tolerance;
  }
  EXPECT_FALSE(treecodeParametersForTolerance(1e-7).singlePrecision);
}
