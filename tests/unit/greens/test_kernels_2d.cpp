// 2D Stokeslet, stresslet and pressure, free space (eqs A.8-A.9) and plane wall
// (App. B.1, with T^D evaluated and the doublet pressure of B.8 corrected).
#include "capsula/testing/Constants.hpp"
#include <capsula/greens/FreeSpace2D.hpp>
#include <capsula/greens/Wall2D.hpp>

#include "KernelTesting.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using capsula::testing::pi;

namespace kernels_2d_test { // the file's own names, apart from those of the files compiled with it
namespace {

using namespace capsula::greens;
using capsula::greens::testing::centralDifference;
using capsula::greens::testing::minus;
using capsula::greens::testing::norm;
using capsula::greens::testing::Tensors;
using V2 = capsula::greens::testing::Vec<2>;

struct PointPair {
  V2 x;  // field point
  V2 x0; // pole
  double distance;
};

// Field points and poles in the fluid (y > 0.2), at least 0.3 apart.
std::vector<PointPair> samplePairs(int count)
{
  std::mt19937 generator(411);
  std::uniform_real_distribution<double> tangential(-2.0, 2.0), height(0.2, 3.0);
  std::vector<PointPair> pairs;
  while (static_cast<int>(pairs.size()) < count) {
    const V2 x{tangential(generator), height(generator)};
    const V2 x0{tangential(generator), height(generator)};
    const double d = norm<2>(minus<2>(x, x0));
    if (d > 0.3) {
      pairs.push_back({x, x0, d});
    }
  }
  return pairs;
}

template <class Kernel>
class StokesKernel2D : public ::testing::Test {};
using Kernels = ::testing::Types<FreeSpace2D, Wall2D>;
TYPED_TEST_SUITE(StokesKernel2D, Kernels);

TYPED_TEST(StokesKernel2D, Reciprocity)
{
  // G_ij(x, x0) = G_ji(x0, x), which eq A.10 relies on.
  for (const PointPair& p : samplePairs(200)) {
    double forward[2][2], backward[2][2];
    TypeParam::stokeslet(p.x.data(), p.x0.data(), forward);
    TypeParam::stokeslet(p.x0.data(), p.x.data(), backward);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        EXPECT_NEAR(forward[i][j], backward[j][i], 1e-14) << i << j; // O(1) terms, few ulps
      }
    }
  }
}

TYPED_TEST(StokesKernel2D, StressIsSymmetric)
{
  for (const PointPair& p : samplePairs(50)) {
    const Tensors<TypeParam> t(p.x, p.x0);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        for (int k = 0; k < 2; ++k) {
          EXPECT_NEAR(t.T[i][j][k], t.T[k][j][i], 1e-14 / p.distance);
        }
      }
    }
  }
}

// Steps 1e-3 d for the 5-point stencil: truncation ~1e-12, round-off ~1e-13 relative to
// the derivative's scale; 1e-9 of that scale still catches any wrong term (O(1) errors).
constexpr double relativeStep = 1e-3;
constexpr double differenceTolerance = 1e-9;

TYPED_TEST(StokesKernel2D, VelocityIsDivergenceFree)
{
  for (const PointPair& p : samplePairs(60)) {
    const double step = relativeStep * p.distance;
    const double scale = 1.0 / p.distance; // |grad G|
    for (int j = 0; j < 2; ++j) {
      double divergence = 0.0;
      for (int i = 0; i < 2; ++i) {
        divergence +=
            centralDifference<2>([&](const V2& x) { return Tensors<TypeParam>(x, p.x0).G[i][j]; }, p.x, i, step);
      }
      EXPECT_NEAR(divergence, 0.0, differenceTolerance * scale) << "j = " << j;
    }
  }
}

TYPED_TEST(StokesKernel2D, StressIsPressurePlusRateOfStrain)
{
  // T_ijk = -P_j delta_ik + dG_ij/dx_k + dG_kj/dx_i (mu = 1).
  for (const PointPair& p : samplePairs(40)) {
    const double step = relativeStep * p.distance;
    const double scale = 1.0 / p.distance;
    const Tensors<TypeParam> t(p.x, p.x0);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        for (int k = 0; k < 2; ++k) {
          const double dGijdxk =
              centralDifference<2>([&](const V2& x) { return Tensors<TypeParam>(x, p.x0).G[i][j]; }, p.x, k, step);
          const double dGkjdxi =
              centralDifference<2>([&](const V2& x) { return Tensors<TypeParam>(x, p.x0).G[k][j]; }, p.x, i, step);
          const double expected = -(i == k ? t.P[j] : 0.0) + dGijdxk + dGkjdxi;
          EXPECT_NEAR(t.T[i][j][k], expected, differenceTolerance * scale) << i << j << k;
        }
      }
    }
  }
}

TYPED_TEST(StokesKernel2D, StressIsInEquilibrium)
{
  for (const PointPair& p : samplePairs(40)) {
    const double step = relativeStep * p.distance;
    const double scale = 1.0 / (p.distance * p.distance); // |grad T|
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        double divergence = 0.0;
        for (int k = 0; k < 2; ++k) {
          divergence +=
              centralDifference<2>([&](const V2& x) { return Tensors<TypeParam>(x, p.x0).T[i][j][k]; }, p.x, k, step);
        }
        EXPECT_NEAR(divergence, 0.0, differenceTolerance * scale) << i << j;
      }
    }
  }
}

TYPED_TEST(StokesKernel2D, StressletIsSolenoidalInThePole)
{
  // The double-layer velocity of eq A.10 (index j, as a function of x0) is a Stokes flow.
  for (const PointPair& p : samplePairs(40)) {
    const double step = relativeStep * p.distance;
    const double scale = 1.0 / (p.distance * p.distance);
    for (int i = 0; i < 2; ++i) {
      for (int k = 0; k < 2; ++k) {
        double divergence = 0.0;
        for (int j = 0; j < 2; ++j) {
          divergence +=
              centralDifference<2>([&](const V2& x0) { return Tensors<TypeParam>(p.x, x0).T[i][j][k]; }, p.x0, j, step);
        }
        EXPECT_NEAR(divergence, 0.0, differenceTolerance * scale) << i << k;
      }
    }
  }
}

// Integrals over the circle |x - centre| = radius by the trapezoid rule in the angle
// (geometric convergence for these periodic analytic integrands).
struct CircleIntegrals {
  double tractionOfStresslet[2][2] = {}; // int T_ijk n_k dl
  double fluxOfStokeslet[2] = {};        // int n_i G_ij dl
  double stokeslet[2][2] = {};           // int G_ij dl
};

template <class Kernel>
CircleIntegrals integrateOverCircle(const V2& centre, double radius, const V2& pole)
{
  const int count = 400;
  CircleIntegrals result;
  for (int a = 0; a < count; ++a) {
    const double angle = 2.0 * pi * a / count;
    const V2 n{std::cos(angle), std::sin(angle)};
    const V2 x{centre[0] + radius * n[0], centre[1] + radius * n[1]};
    const double dl = radius * 2.0 * pi / count;
    const Tensors<Kernel> t(x, pole);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        for (int k = 0; k < 2; ++k) {
          result.tractionOfStresslet[i][j] += t.T[i][j][k] * n[k] * dl;
        }
        result.fluxOfStokeslet[j] += n[i] * t.G[i][j] * dl;
        result.stokeslet[i][j] += t.G[i][j] * dl;
      }
    }
  }
  return result;
}

// A circle wholly in the fluid (gap 0.6 to the wall); the nearest poles are 0.29 inside and
// 0.33 outside it, so the trapezoid error (~0.75^400) is nil and only the round-off of 400
// terms remains (~1e-13 of the O(10) values); 1e-11 leaves a wide margin.
const V2 circleCentre{0.2, 1.6};
constexpr double circleRadius = 1.0;
const std::vector<V2> polesInside{{0.2, 1.6}, {0.5, 1.1}, {-0.3, 2.1}};
const std::vector<V2> polesOutside{{0.5, 0.3}, {2.5, 1.5}, {0.1, 3.2}};
constexpr double circleTolerance = 1e-11;

TYPED_TEST(StokesKernel2D, TractionOfStressletOverClosedCurve)
{
  // -4 pi delta_ij with the pole inside, 0 outside (the 2D analogue of the ERRATA identity).
  for (const V2& pole : polesInside) {
    const CircleIntegrals c = integrateOverCircle<TypeParam>(circleCentre, circleRadius, pole);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        EXPECT_NEAR(c.tractionOfStresslet[i][j], i == j ? -4.0 * pi : 0.0, circleTolerance) << i << j;
      }
    }
  }
  for (const V2& pole : polesOutside) {
    const CircleIntegrals c = integrateOverCircle<TypeParam>(circleCentre, circleRadius, pole);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        EXPECT_NEAR(c.tractionOfStresslet[i][j], 0.0, circleTolerance) << i << j;
      }
    }
  }
}

TYPED_TEST(StokesKernel2D, StokesletHasNoFluxThroughClosedCurve)
{
  std::vector<V2> poles = polesInside;
  poles.insert(poles.end(), polesOutside.begin(), polesOutside.end());
  for (const V2& pole : poles) {
    const CircleIntegrals c = integrateOverCircle<TypeParam>(circleCentre, circleRadius, pole);
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(c.fluxOfStokeslet[j], 0.0, circleTolerance) << j;
    }
  }
}

TEST(FreeSpaceKernel2D, SingleLayerOfUniformDensityOnCircle)
{
  // For every pole inside: int -ln r dl = -2 pi a ln a (mean value of the log potential)
  // and int xh_i xh_j / r^2 dl = pi a delta_ij (a residue computation), so
  // int_C G_ij dl = pi a (1 - 2 ln a) delta_ij.
  for (double radius : {0.3, 1.0, 2.5}) {
    for (const V2& offset : {V2{0, 0}, V2{0.3, -0.4}}) {
      const V2 pole{circleCentre[0] + radius * offset[0], circleCentre[1] + radius * offset[1]};
      const CircleIntegrals c = integrateOverCircle<FreeSpace2D>(circleCentre, radius, pole);
      const double expected = pi * radius * (1.0 - 2.0 * std::log(radius));
      for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) {
          EXPECT_NEAR(c.stokeslet[i][j], i == j ? expected : 0.0, circleTolerance * radius)
              << "a = " << radius << " " << i << j;
        }
      }
    }
  }
}

TEST(FreeSpaceKernel2D, ClosedForms)
{
  const V2 x{3.0, -4.0}; // r = 5
  const V2 x0{0.0, 0.0};
  const Tensors<FreeSpace2D> t(x, x0);
  EXPECT_DOUBLE_EQ(t.G[0][0], -std::log(5.0) + 9.0 / 25.0);
  EXPECT_DOUBLE_EQ(t.G[0][1], -12.0 / 25.0);
  EXPECT_DOUBLE_EQ(t.T[0][0][1], -4.0 * (3.0 * 3.0 * -4.0) / 625.0);
  EXPECT_DOUBLE_EQ(t.P[1], 2.0 * -4.0 / 25.0);
}

TEST(WallKernel2D, VelocityVanishesOnTheWall)
{
  std::mt19937 generator(99);
  std::uniform_real_distribution<double> tangential(-3.0, 3.0), height(0.05, 4.0);
  for (int sample = 0; sample < 500; ++sample) {
    const V2 x0{tangential(generator), height(generator)};
    const V2 x{tangential(generator), 0.0};
    double G[2][2];
    Wall2D::stokeslet(x.data(), x0.data(), G);
    // Cancelling parts of size |ln r| and O(1): a few ulps of that.
    const double scale = std::max(1.0, std::abs(std::log(norm<2>(minus<2>(x, x0)))));
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        EXPECT_NEAR(G[i][j], 0.0, 1e-13 * scale) << i << j;
      }
    }
  }
}

} // namespace

} // namespace kernels_2d_test
