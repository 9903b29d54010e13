// 3D Stokeslet, stresslet and pressure, free space (eqs 3.11-3.12) and plane wall (Blake,
// App. B.2 with the ERRATA fixes): identities that fail on any wrong sign or factor.
#include "capsula/testing/Constants.hpp"
#include <capsula/greens/FreeSpace3D.hpp>
#include <capsula/greens/Wall3D.hpp>

#include <capsula/quadrature/GaussLegendre.hpp>

#include "KernelTesting.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using capsula::testing::pi;

namespace {

using namespace capsula::greens;
using capsula::greens::testing::centralDifference;
using capsula::greens::testing::minus;
using capsula::greens::testing::norm;
using capsula::greens::testing::Tensors;
using V3 = capsula::greens::testing::Vec<3>;

struct PointPair {
  V3 x;  // field point
  V3 x0; // pole
  double distance;
};

// Field points and poles in the fluid (y > 0.2), at least 0.3 apart: the finite-difference
// steps below are scaled by the distance, so these are all comparable.
std::vector<PointPair> samplePairs(int count)
{
  std::mt19937 generator(20240611);
  std::uniform_real_distribution<double> tangential(-2.0, 2.0), height(0.2, 3.0);
  std::vector<PointPair> pairs;
  while (static_cast<int>(pairs.size()) < count) {
    const V3 x{tangential(generator), height(generator), tangential(generator)};
    const V3 x0{tangential(generator), height(generator), tangential(generator)};
    const double d = norm<3>(minus<3>(x, x0));
    if (d > 0.3) {
      pairs.push_back({x, x0, d});
    }
  }
  return pairs;
}

template <class Kernel>
class StokesKernel3D : public ::testing::Test {};
using Kernels = ::testing::Types<FreeSpace3D, Wall3D>;
TYPED_TEST_SUITE(StokesKernel3D, Kernels);

TYPED_TEST(StokesKernel3D, Reciprocity)
{
  // G_ij(x, x0) = G_ji(x0, x): what lets eq 3.13 integrate over the pole's partner.
  for (const PointPair& p : samplePairs(200)) {
    double forward[3][3], backward[3][3];
    TypeParam::stokeslet(p.x.data(), p.x0.data(), forward);
    TypeParam::stokeslet(p.x0.data(), p.x.data(), backward);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        // Different cancellations on each side: a few ulps of the 1/d scale.
        EXPECT_NEAR(forward[i][j], backward[j][i], 1e-14 / p.distance) << i << j;
      }
    }
  }
}

TYPED_TEST(StokesKernel3D, StressIsSymmetric)
{
  for (const PointPair& p : samplePairs(50)) {
    const Tensors<TypeParam> t(p.x, p.x0);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(t.T[i][j][k], t.T[k][j][i], 1e-14 / (p.distance * p.distance));
        }
      }
    }
  }
}

// Finite differences use a step 1e-3 d: the 5-point stencil's truncation is ~(1e-3)^4 = 1e-12
// relative and its round-off ~eps / 1e-3 = 1e-13 relative to the derivative scale, so the
// tolerances 1e-9 of that scale leave room for the constants and still catch any wrong term
// (a wrong sign or factor gives O(1) relative errors).
constexpr double relativeStep = 1e-3;
constexpr double differenceTolerance = 1e-9;

TYPED_TEST(StokesKernel3D, VelocityIsDivergenceFree)
{
  for (const PointPair& p : samplePairs(40)) {
    const double step = relativeStep * p.distance;
    const double scale = 1.0 / (p.distance * p.distance); // |grad G|
    for (int j = 0; j < 3; ++j) {
      double divergence = 0.0;
      for (int i = 0; i < 3; ++i) {
        divergence +=
            centralDifference<3>([&](const V3& x) { return Tensors<TypeParam>(x, p.x0).G[i][j]; }, p.x, i, step);
      }
      EXPECT_NEAR(divergence, 0.0, differenceTolerance * scale) << "j = " << j;
    }
  }
}

TYPED_TEST(StokesKernel3D, StressIsPressurePlusRateOfStrain)
{
  // T_ijk = -P_j delta_ik + dG_ij/dx_k + dG_kj/dx_i (mu = 1): ties T and P to G.
  for (const PointPair& p : samplePairs(25)) {
    const double step = relativeStep * p.distance;
    const double scale = 1.0 / (p.distance * p.distance);
    const Tensors<TypeParam> t(p.x, p.x0);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          const double dGijdxk =
              centralDifference<3>([&](const V3& x) { return Tensors<TypeParam>(x, p.x0).G[i][j]; }, p.x, k, step);
          const double dGkjdxi =
              centralDifference<3>([&](const V3& x) { return Tensors<TypeParam>(x, p.x0).G[k][j]; }, p.x, i, step);
          const double expected = -(i == k ? t.P[j] : 0.0) + dGijdxk + dGkjdxi;
          EXPECT_NEAR(t.T[i][j][k], expected, differenceTolerance * scale) << i << j << k;
        }
      }
    }
  }
}

TYPED_TEST(StokesKernel3D, StressIsInEquilibrium)
{
  // Stokes momentum balance away from the pole: dT_ijk/dx_k = 0.
  for (const PointPair& p : samplePairs(25)) {
    const double step = relativeStep * p.distance;
    const double scale = std::pow(p.distance, -3); // |grad T|
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        double divergence = 0.0;
        for (int k = 0; k < 3; ++k) {
          divergence +=
              centralDifference<3>([&](const V3& x) { return Tensors<TypeParam>(x, p.x0).T[i][j][k]; }, p.x, k, step);
        }
        EXPECT_NEAR(divergence, 0.0, differenceTolerance * scale) << i << j;
      }
    }
  }
}

TYPED_TEST(StokesKernel3D, StressletIsSolenoidalInThePole)
{
  // T_ijk(x, x0) n_k as a function of x0 is the double-layer velocity (index j) of eq 3.13,
  // a Stokes flow: d/dx0_j T_ijk(x, x0) = 0.
  for (const PointPair& p : samplePairs(25)) {
    const double step = relativeStep * p.distance;
    const double scale = std::pow(p.distance, -3);
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) {
        double divergence = 0.0;
        for (int j = 0; j < 3; ++j) {
          divergence +=
              centralDifference<3>([&](const V3& x0) { return Tensors<TypeParam>(p.x, x0).T[i][j][k]; }, p.x0, j, step);
        }
        EXPECT_NEAR(divergence, 0.0, differenceTolerance * scale) << i << k;
      }
    }
  }
}

// Integrals over the sphere |x - centre| = radius: Gauss-Legendre in cos(theta) times the
// trapezoid rule in phi, both spectrally accurate for these smooth integrands.
struct SphereIntegrals {
  double tractionOfStresslet[3][3] = {}; // int T_ijk n_k dS
  double fluxOfStokeslet[3] = {};        // int n_i G_ij dS
  double stokeslet[3][3] = {};           // int G_ij dS
};

template <class Kernel>
SphereIntegrals integrateOverSphere(const V3& centre, double radius, const V3& pole)
{
  const int polar = 64, azimuthal = 128;
  const auto gauss = capsula::quadrature::gaussLegendre(polar, -1.0, 1.0);
  SphereIntegrals result;
  for (int a = 0; a < polar; ++a) {
    const double cosTheta = gauss.points[a];
    const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
    for (int b = 0; b < azimuthal; ++b) {
      const double phi = 2.0 * pi * b / azimuthal;
      const V3 n{sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
      const V3 x{centre[0] + radius * n[0], centre[1] + radius * n[1], centre[2] + radius * n[2]};
      const double dS = radius * radius * gauss.weights[a] * (2.0 * pi / azimuthal);
      const Tensors<Kernel> t(x, pole);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          for (int k = 0; k < 3; ++k) {
            result.tractionOfStresslet[i][j] += t.T[i][j][k] * n[k] * dS;
          }
          result.fluxOfStokeslet[j] += n[i] * t.G[i][j] * dS;
          result.stokeslet[i][j] += t.G[i][j] * dS;
        }
      }
    }
  }
  return result;
}

// A sphere wholly in the fluid (gap 0.6 to the wall), poles inside and outside it.
const V3 sphereCentre{0.2, 1.6, -0.1};
constexpr double sphereRadius = 1.0;
const std::vector<V3> polesInside{{0.2, 1.6, -0.1}, {0.5, 1.2, 0.1}, {-0.3, 2.0, -0.4}};
const std::vector<V3> polesOutside{{0.5, 0.3, 2.1}, {2.5, 1.5, 0.3}, {0.1, 3.2, -0.2}};

// The closest pole is 0.29 from the surface: 32 x 64 points already reach round-off
// (1e-13 to 1e-12 on the O(25) values from 8192 terms of up to ~70); 64 x 128 keeps a
// margin in resolution and 1e-11 one in round-off.
constexpr double sphereTolerance = 1e-11;

TYPED_TEST(StokesKernel3D, TractionOfStressletOverClosedSurface)
{
  // -8 pi delta_ij with the pole inside, 0 outside (ERRATA, eq 3.44). For the wall kernel
  // the images lie below the wall, outside the sphere, and add nothing.
  for (const V3& pole : polesInside) {
    const SphereIntegrals s = integrateOverSphere<TypeParam>(sphereCentre, sphereRadius, pole);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(s.tractionOfStresslet[i][j], i == j ? -8.0 * pi : 0.0, sphereTolerance) << i << j;
      }
    }
  }
  for (const V3& pole : polesOutside) {
    const SphereIntegrals s = integrateOverSphere<TypeParam>(sphereCentre, sphereRadius, pole);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(s.tractionOfStresslet[i][j], 0.0, sphereTolerance) << i << j;
      }
    }
  }
}

TYPED_TEST(StokesKernel3D, StokesletHasNoFluxThroughClosedSurface)
{
  std::vector<V3> poles = polesInside;
  poles.insert(poles.end(), polesOutside.begin(), polesOutside.end());
  for (const V3& pole : poles) {
    const SphereIntegrals s = integrateOverSphere<TypeParam>(sphereCentre, sphereRadius, pole);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(s.fluxOfStokeslet[j], 0.0, sphereTolerance) << j;
    }
  }
}

TEST(FreeSpaceKernel3D, SingleLayerOfUniformDensityOnSphere)
{
  // Uniform traction on a sphere drives a rigid translation inside it:
  // int_S G_ij dS = 16 pi a / 3 delta_ij for every pole inside (4 pi a + 4 pi a / 3).
  for (double radius : {0.5, 1.0, 2.0}) {
    for (const V3& offset : {V3{0, 0, 0}, V3{0.3, -0.2, 0.1}}) {
      const V3 pole{sphereCentre[0] + radius * offset[0], sphereCentre[1] + radius * offset[1],
                    sphereCentre[2] + radius * offset[2]};
      const SphereIntegrals s = integrateOverSphere<FreeSpace3D>(sphereCentre, radius, pole);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          EXPECT_NEAR(s.stokeslet[i][j], i == j ? 16.0 * pi * radius / 3.0 : 0.0, sphereTolerance * radius)
              << "a = " << radius << " " << i << j;
        }
      }
    }
  }
}

TEST(FreeSpaceKernel3D, ClosedForms)
{
  const V3 x{1.0, 2.0, -2.0}; // r = 3
  const V3 x0{0.0, 0.0, 0.0};
  const Tensors<FreeSpace3D> t(x, x0);
  EXPECT_DOUBLE_EQ(t.G[0][0], 1.0 / 3.0 + 1.0 / 27.0);
  EXPECT_DOUBLE_EQ(t.G[1][2], -4.0 / 27.0);
  EXPECT_DOUBLE_EQ(t.T[0][1][2], -6.0 * (1.0 * 2.0 * -2.0) / 243.0);
  EXPECT_DOUBLE_EQ(t.P[1], 2.0 * 2.0 / 27.0);
}

TEST(WallKernel3D, VelocityVanishesOnTheWall)
{
  // Blake's no-slip condition G^W_ij(x, x0) = 0 for x on y = 0, any pole above it.
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> tangential(-3.0, 3.0), height(0.05, 4.0);
  for (int sample = 0; sample < 500; ++sample) {
    const V3 x0{tangential(generator), height(generator), tangential(generator)};
    const V3 x{tangential(generator), 0.0, tangential(generator)};
    double G[3][3];
    Wall3D::stokeslet(x.data(), x0.data(), G);
    const double scale = 1.0 / norm<3>(minus<3>(x, x0)); // the size of each cancelling part
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(G[i][j], 0.0, 1e-12 * scale) << i << j; // terms of size ~scale cancel
      }
    }
  }
}

TEST(WallKernel3D, ImageCorrectionAtThePole)
{
  // G^W - G^FS at x -> x0 is -3/(4h) for the tangential and -3/(2h) for the normal force,
  // no coupling. With u = G g / (8 pi mu) and a sphere's drag 6 pi mu a this is Lorentz's
  // mobility correction 1 - (9/16) a/h parallel and 1 - (9/8) a/h normal to the wall.
  for (double h : {0.1, 1.0, 7.5}) {
    const V3 x0{0.4, h, -1.3};
    // Average at x0 +- delta along x: the smooth image part's linear change cancels, leaving
    // O((delta/h)^2) = 1e-8; the cancellation of 1/delta terms costs eps h / delta = 1e-12.
    const double delta = 1e-4 * h;
    double correction[3][3] = {};
    for (double sign : {-1.0, 1.0}) {
      const V3 x{x0[0] + sign * delta, x0[1], x0[2]};
      double wall[3][3], freeSpace[3][3];
      Wall3D::stokeslet(x.data(), x0.data(), wall);
      FreeSpace3D::stokeslet(x.data(), x0.data(), freeSpace);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          correction[i][j] += 0.5 * (wall[i][j] - freeSpace[i][j]);
        }
      }
    }
    const double expected[3] = {-3.0 / (4.0 * h), -3.0 / (2.0 * h), -3.0 / (4.0 * h)};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(correction[i][j], i == j ? expected[i] : 0.0, 1e-7 / h) << h << " " << i << j;
      }
    }
  }
}

TEST(WallKernel3D, ApproachesFreeSpaceFarFromTheWall)
{
  // With x - x0 fixed and h -> infinity, G^W - G^FS = O(1/h): halving it per doubling of h.
  const V3 offset{0.3, -0.2, 0.5};
  double previous = 0.0;
  for (double h : {100.0, 200.0, 400.0}) {
    const V3 x0{0.0, h, 0.0};
    const V3 x{offset[0], h + offset[1], offset[2]};
    double wall[3][3], freeSpace[3][3];
    Wall3D::stokeslet(x.data(), x0.data(), wall);
    FreeSpace3D::stokeslet(x.data(), x0.data(), freeSpace);
    const double difference = std::abs(wall[1][1] - freeSpace[1][1]);
    EXPECT_NEAR(difference * h, 1.5, 0.02); // -> 3/2 (the pole correction) up to O(1/h)
    if (previous > 0.0) {
      EXPECT_NEAR(previous / difference, 2.0, 0.02);
    }
    previous = difference;
  }
}

} // namespace
