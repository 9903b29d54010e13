// The quadratic-triangle shape functions (eq 3.19 with the ERRATA fix) and the
// element map built on them (eqs 3.20-3.24).
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/ShapeFunctions.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace capsula::mesh;

namespace {

/// Random alpha, beta, gamma in (0.3, 0.7): midside nodes well off the edge middles.
std::vector<ShapeParameters> distortedParameters()
{
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> u(0.3, 0.7);
  std::vector<ShapeParameters> all{ShapeParameters{}};
  for (int i = 0; i < 50; ++i) {
    all.push_back({u(rng), u(rng), u(rng)});
  }
  return all;
}

/// Points spread over the reference triangle, edges and corners included.
std::vector<std::array<double, 2>> samplePoints()
{
  std::vector<std::array<double, 2>> points;
  const int n = 7;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      points.push_back({static_cast<double>(i) / n, static_cast<double>(j) / n});
    }
  }
  points.push_back({0.123, 0.456});
  return points;
}

} // namespace

TEST(MeshShapeFunctions, KroneckerDeltaAtTheSixNodes)
{
  for (const ShapeParameters& p : distortedParameters()) {
    for (int j = 0; j < 6; ++j) {
      const auto c = nodeParametricCoordinates(p, j);
      double phi[6];
      shapeFunctions(p, c[0], c[1], phi);
      for (int i = 0; i < 6; ++i) {
        // Rational expressions of O(1) values: round-off only.
        EXPECT_NEAR(phi[i], i == j ? 1.0 : 0.0, 1e-13) << "phi_" << i + 1 << " at node " << j + 1 << ", alpha "
                                                       << p.alpha << " beta " << p.beta << " gamma " << p.gamma;
      }
    }
  }
}

TEST(MeshShapeFunctions, PartitionOfUnityAndDerivativesSumToZero)
{
  for (const ShapeParameters& p : distortedParameters()) {
    for (const auto& pt : samplePoints()) {
      double phi[6], dXi[6], dEta[6];
      shapeFunctions(p, pt[0], pt[1], phi);
      shapeFunctionDerivatives(p, pt[0], pt[1], dXi, dEta);
      double sum = 0.0, sumXi = 0.0, sumEta = 0.0;
      for (int i = 0; i < 6; ++i) {
        sum += phi[i];
        sumXi += dXi[i];
        sumEta += dEta[i];
      }
      // phi_1 and its derivatives are defined as 1 - (the others): round-off only. This
      // guards that definition; the delta test above is what pins phi_2..phi_6.
      EXPECT_NEAR(sum, 1.0, 1e-13);
      EXPECT_NEAR(sumXi, 0.0, 1e-12);
      EXPECT_NEAR(sumEta, 0.0, 1e-12);
    }
  }
}

TEST(MeshShapeFunctions, DerivativesMatchCentralDifferences)
{
  const double h = 1e-6;
  for (const ShapeParameters& p : distortedParameters()) {
    for (const auto& pt : samplePoints()) {
      double dXi[6], dEta[6], plus[6], minus[6];
      shapeFunctionDerivatives(p, pt[0], pt[1], dXi, dEta);
      for (int dir = 0; dir < 2; ++dir) {
        const double dx = dir == 0 ? h : 0.0, dy = dir == 1 ? h : 0.0;
        shapeFunctions(p, pt[0] + dx, pt[1] + dy, plus);
        shapeFunctions(p, pt[0] - dx, pt[1] - dy, minus);
        for (int i = 0; i < 6; ++i) {
          const double fd = (plus[i] - minus[i]) / (2.0 * h);
          // Quadratics: the central difference has no truncation error, only round-off
          // ~ 1e-16 * |phi| / h with coefficients up to 1/(0.3*0.7) ~ 5.
          EXPECT_NEAR(fd, dir == 0 ? dXi[i] : dEta[i], 1e-8) << "i " << i << " dir " << dir;
        }
      }
    }
  }
}

TEST(MeshShapeFunctions, QuadraticMapReproducesQuadraticFieldsExactly)
{
  // A quadratic field f(xi, eta) sampled at the six nodes is interpolated exactly by
  // eq 3.18 on any element: the six shape functions span all quadratics.
  const auto f = [](double xi, double eta) {
    return 0.7 - 1.3 * xi + 2.1 * eta + 0.9 * xi * xi - 1.7 * xi * eta + 3.2 * eta * eta;
  };
  const auto dfXi = [](double xi, double eta) { return -1.3 + 1.8 * xi - 1.7 * eta; };
  const auto dfEta = [](double xi, double eta) { return 2.1 - 1.7 * xi + 6.4 * eta; };
  for (const ShapeParameters& p : distortedParameters()) {
    double nodal[6];
    for (int i = 0; i < 6; ++i) {
      const auto c = nodeParametricCoordinates(p, i);
      nodal[i] = f(c[0], c[1]);
    }
    for (const auto& pt : samplePoints()) {
      double phi[6], dXi[6], dEta[6];
      shapeFunctions(p, pt[0], pt[1], phi);
      shapeFunctionDerivatives(p, pt[0], pt[1], dXi, dEta);
      double value = 0.0, gXi = 0.0, gEta = 0.0;
      for (int i = 0; i < 6; ++i) {
        value += nodal[i] * phi[i];
        gXi += nodal[i] * dXi[i];
        gEta += nodal[i] * dEta[i];
      }
      EXPECT_NEAR(value, f(pt[0], pt[1]), 1e-12); // round-off of O(10) terms
      EXPECT_NEAR(gXi, dfXi(pt[0], pt[1]), 1e-11);
      EXPECT_NEAR(gEta, dfEta(pt[0], pt[1]), 1e-11);
    }
  }
}

TEST(MeshShapeFunctions, AsPrintedPhi3WouldNotVanishAtNode5)
{
  // Guard for the ERRATA: with the printed (beta - gamma - 1)/gamma, phi_3 at node 5
  // is (1-gamma)(1-gamma-beta+(beta-gamma-1)) = -2 gamma (1-gamma)/(1-beta) != 0; the
  // corrected function used here vanishes there.
  const ShapeParameters p{0.45, 0.55, 0.4};
  double phi[6];
  shapeFunctions(p, p.gamma, 1.0 - p.gamma, phi);
  EXPECT_NEAR(phi[2], 0.0, 1e-15);
  const double eta = 1.0 - p.gamma, xi = p.gamma;
  const double printed = eta * (eta - p.beta + (p.beta - p.gamma - 1.0) / p.gamma * xi) / (1.0 - p.beta);
  EXPECT_GT(std::abs(printed), 0.1);
}

TEST(MeshElementGeometry, FlatElementHasConstantMetricAndNormal)
{
  // A planar element with straight edges (midside nodes at the alpha, beta, gamma
  // fractions of the edges): the map is affine, x_xi = x2 - x1, x_eta = x3 - x1.
  const Vec3 x1(0.2, -0.1, 0.3), x2(1.4, 0.2, 0.3), x3(0.1, 0.9, 0.3);
  const ShapeParameters p{0.35, 0.62, 0.44};
  const ElementNodes x{x1, x2, x3, x1 + p.alpha * (x2 - x1), x2 + (1.0 - p.gamma) * (x3 - x2), x1 + p.beta * (x3 - x1)};
  const ShapeParameters computed = shapeParameters(x);
  EXPECT_NEAR(computed.alpha, p.alpha, 1e-14); // eq 3.17 recovers the fractions
  EXPECT_NEAR(computed.beta, p.beta, 1e-14);
  EXPECT_NEAR(computed.gamma, p.gamma, 1e-14);
  const Vec3 areaVector = (x2 - x1).cross(x3 - x1);
  for (const auto& pt : samplePoints()) {
    const SurfacePoint s = evaluateSurfacePoint(x, computed, pt[0], pt[1]);
    EXPECT_NEAR((s.position - (x1 + pt[0] * (x2 - x1) + pt[1] * (x3 - x1))).norm(), 0.0, 1e-14);
    EXPECT_NEAR((s.tangentXi - (x2 - x1)).norm(), 0.0, 1e-13);
    EXPECT_NEAR((s.tangentEta - (x3 - x1)).norm(), 0.0, 1e-13);
    EXPECT_NEAR(s.metric, areaVector.norm(), 1e-13);
    EXPECT_NEAR((s.normal - Vec3(0.0, 0.0, 1.0)).norm(), 0.0, 1e-14);
  }
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR((evaluateAtNode(x, computed, i).position - x[i]).norm(), 0.0, 1e-14);
  }
}

TEST(MeshElementGeometry, TangentsMatchCentralDifferencesOnACurvedElement)
{
  const ElementNodes x{Vec3(0.0, 0.0, 0.0),   Vec3(1.0, 0.1, 0.2), Vec3(0.1, 1.0, -0.1),
                       Vec3(0.45, 0.0, 0.25), Vec3(0.6, 0.6, 0.3), Vec3(-0.05, 0.5, 0.15)};
  const ShapeParameters p = shapeParameters(x);
  const double h = 1e-6;
  for (const auto& pt : samplePoints()) {
    const SurfacePoint s = evaluateSurfacePoint(x, p, pt[0], pt[1]);
    const Vec3 fdXi = (surfacePosition(x, p, pt[0] + h, pt[1]) - surfacePosition(x, p, pt[0] - h, pt[1])) / (2 * h);
    const Vec3 fdEta = (surfacePosition(x, p, pt[0], pt[1] + h) - surfacePosition(x, p, pt[0], pt[1] - h)) / (2 * h);
    EXPECT_NEAR((fdXi - s.tangentXi).norm(), 0.0, 1e-8); // quadratic map: round-off / h only
    EXPECT_NEAR((fdEta - s.tangentEta).norm(), 0.0, 1e-8);
    EXPECT_NEAR(s.normal.norm(), 1.0, 1e-14);
    EXPECT_NEAR(s.normal.dot(s.tangentXi), 0.0, 1e-13);
    EXPECT_NEAR(s.normal.dot(s.tangentEta), 0.0, 1e-13);
    EXPECT_NEAR(s.metric, s.tangentXi.cross(s.tangentEta).norm(), 1e-14);
  }
}
