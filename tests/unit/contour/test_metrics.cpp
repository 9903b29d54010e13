// Shape metrics (App. A.9.1, eq 4.2): area, length, centroid, second moment, D12 and
// the cell length, against exact ellipse values and under rigid motions.
#include "capsula/testing/Constants.hpp"
#include "capsula/testing/ConvergenceOrder.hpp"
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/contour/InitialShapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using capsula::testing::pi;

namespace {

using capsula::contour::Contour;
using capsula::contour::EllipseShape;

using capsula::testing::fittedOrder;

/// Perimeter of the ellipse with semi-axes a, b by the arithmetic-geometric mean:
/// P = 2 pi / AGM(a, b) (a^2 - sum_n 2^(n-1) c_n^2), c_0^2 = a^2 - b^2.
double ellipsePerimeter(double a, double b)
{
  double an = a, bn = b, sum = 0.5 * (a * a - b * b);
  for (int n = 1; n < 12; ++n) { // quadratic convergence: 6 steps reach round-off
    const double c = 0.5 * (an - bn);
    const double next = 0.5 * (an + bn);
    bn = std::sqrt(an * bn);
    an = next;
    sum += std::ldexp(c * c, n - 1);
  }
  return 2.0 * pi / an * (a * a - sum);
}

EllipseShape testEllipse()
{
  EllipseShape shape;
  shape.aspectRatio = 0.25; // the thesis' flattest cell: a = 0.5, b = 2
  shape.centre = Eigen::Vector2d(0.3, 1.7);
  shape.orientation = 0.4;
  shape.firstNodeAngle = 0.2;
  return shape;
}

TEST(ContourMetrics, PerimeterReferenceIsRight)
{
  EXPECT_NEAR(ellipsePerimeter(1.0, 1.0), 2.0 * pi, 1e-14);
  // Brute-force trapezoid (spectral for periodic integrands) at 20000 points: 8.57842177515682.
  EXPECT_NEAR(ellipsePerimeter(2.0, 0.5), 8.578421775156833, 1e-13);
}

TEST(ContourMetrics, EllipseAreaLengthAndD12Converge)
{
  const EllipseShape shape = testEllipse();
  const double a = 0.5, b = 2.0;
  const std::vector<int> pointCounts{16, 32, 64, 128, 256};
  std::vector<double> areaError, lengthError, d12Error, centroidError, orientationError;
  for (int n : pointCounts) {
    const Contour contour(capsula::contour::ellipseNodes(n, shape));
    areaError.push_back(std::abs(capsula::contour::enclosedArea(contour) - pi));
    lengthError.push_back(std::abs(contour.length() - ellipsePerimeter(a, b)));
    d12Error.push_back(std::abs(capsula::contour::taylorDeformation(contour) - (b - a) / (b + a)));
    centroidError.push_back((capsula::contour::centroid(contour) - shape.centre).norm());
    // The major axis is b, across the a-axis at angle 0.4.
    orientationError.push_back(
        std::abs(capsula::contour::equivalentEllipse(contour).orientation - (0.4 + 0.5 * pi - pi)));
    std::printf("  ellipse a/b = 0.25, N = %3d: area %.2e, length %.2e, D12 %.2e, centroid "
                "%.2e, orientation %.2e\n",
                n, areaError.back(), lengthError.back(), d12Error.back(), centroidError.back(),
                orientationError.back());
  }
  const double areaOrder = fittedOrder(pointCounts, areaError);
  const double lengthOrder = fittedOrder(pointCounts, lengthError);
  const double d12Order = fittedOrder(pointCounts, d12Error);
  std::printf("  fitted orders: area %.2f, length %.2f, D12 %.2f\n", areaOrder, lengthOrder, d12Order);
  EXPECT_GT(areaOrder, 3.8); // O(h^4) interpolation integrated: O(h^4) (or better)
  EXPECT_GT(lengthOrder, 3.8);
  EXPECT_GT(d12Order, 3.8);
  EXPECT_LT(d12Error.back(), 1e-8); // 1.7e-9 measured at N = 256
  // The node set is point-symmetric about the centre (N even), so the spline centroid is
  // exact to round-off; the principal direction is good to O(h^4) (0 at N = 256).
  EXPECT_LT(centroidError.back(), 1e-12);
  EXPECT_LT(orientationError.back(), 1e-8);
}

TEST(ContourMetrics, CircleSecondMomentAndZeroDeformation)
{
  const double radius = 0.8;
  const Contour circle(capsula::contour::circleNodes(128, radius, {2.0, -1.0}));
  const Eigen::Matrix2d j = capsula::contour::secondMomentOfArea(circle);
  const double exact = pi * std::pow(radius, 4) / 4.0;
  EXPECT_NEAR(j(0, 0) / exact, 1.0, 1e-7); // spline of a 128-gon: O(h^4) ~ 1e-8
  EXPECT_NEAR(j(1, 1) / exact, 1.0, 1e-7);
  EXPECT_NEAR(j(0, 1) / exact, 0.0, 1e-12); // symmetric node set: zero to round-off
  EXPECT_LT(capsula::contour::taylorDeformation(circle), 1e-8);
}

TEST(ContourMetrics, SecondMomentHasThePositiveOffDiagonalOfATiltedEllipse)
{
  // Semi-axis a = 2 along 45 degrees: mass sits where x y > 0, so J_xy > 0.
  EllipseShape shape;
  shape.aspectRatio = 4.0;
  shape.orientation = 0.25 * pi;
  const Contour contour(capsula::contour::ellipseNodes(128, shape));
  const Eigen::Matrix2d j = capsula::contour::secondMomentOfArea(contour);
  // Exact: R diag(A a^2/4, A b^2/4) R^T with A = pi, a = 2, b = 0.5. The spline of 128
  // nodes at a/b = 4 is good to ~3e-7 (O(h^4)); 1e-6 would still catch any wrong factor.
  EXPECT_NEAR(j(0, 1), pi / 8.0 * (4.0 - 0.25), 1e-6);
  EXPECT_NEAR(j(0, 0), pi / 8.0 * (4.0 + 0.25), 1e-6);
  const auto ellipse = capsula::contour::equivalentEllipse(contour);
  EXPECT_NEAR(ellipse.majorSemiAxis, 2.0, 1e-6);
  EXPECT_NEAR(ellipse.minorSemiAxis, 0.5, 1e-6);
  EXPECT_NEAR(ellipse.orientation, 0.25 * pi, 1e-8);
}

TEST(ContourMetrics, InvariantUnderTranslationAndRotation)
{
  EllipseShape shape = testEllipse();
  shape.aspectRatio = 2.5;
  const Eigen::Matrix2Xd nodes = capsula::contour::ellipseNodes(40, shape);
  const double angle = 1.1;
  Eigen::Matrix2d rotation;
  rotation << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  const Eigen::Vector2d shift(-3.0, 5.5);
  const Eigen::Matrix2Xd moved = (rotation * nodes).colwise() + shift;
  const Contour original(nodes);
  const Contour transformed(moved);

  // Rigid motions commute with chord-length splines exactly: differences are round-off
  // of O(1..10) quantities.
  EXPECT_NEAR(capsula::contour::enclosedArea(transformed), capsula::contour::enclosedArea(original), 1e-12);
  EXPECT_NEAR(transformed.length(), original.length(), 1e-12);
  EXPECT_NEAR(capsula::contour::taylorDeformation(transformed), capsula::contour::taylorDeformation(original), 1e-12);
  EXPECT_NEAR(
      (capsula::contour::centroid(transformed) - (rotation * capsula::contour::centroid(original) + shift)).norm(), 0.0,
      1e-12);
  const Eigen::Matrix2d j = capsula::contour::secondMomentOfArea(original);
  EXPECT_NEAR((capsula::contour::secondMomentOfArea(transformed) - rotation * j * rotation.transpose()).norm(), 0.0,
              1e-12);
  for (int k = 0; k < original.numberOfSegments(); ++k) {
    EXPECT_NEAR(transformed.pointAt(k, 0.3).curvature, original.pointAt(k, 0.3).curvature, 1e-11);
    EXPECT_NEAR((transformed.pointAt(k, 0.3).normal - rotation * original.pointAt(k, 0.3).normal).norm(), 0.0, 1e-13);
  }
}

TEST(ContourMetrics, CellLengthUsesSplineExtremes)
{
  // Nodes straddle the ends of the x-axis (half a step off): node extremes miss 2a by
  // O(h^2); the stationary points of the spline pieces recover it to O(h^4).
  const std::vector<int> pointCounts{32, 64, 128, 256};
  std::vector<double> nodeError, splineError, heightError;
  for (int n : pointCounts) {
    EllipseShape shape;
    shape.aspectRatio = 4.0; // a = 2 along x, b = 0.5
    shape.firstNodeAngle = pi / n;
    const Contour contour(capsula::contour::ellipseNodes(n, shape));
    const double nodeLength = contour.nodes().row(0).maxCoeff() - contour.nodes().row(0).minCoeff();
    nodeError.push_back(std::abs(nodeLength - 4.0));
    splineError.push_back(std::abs(capsula::contour::cellLength(contour) - 4.0));
    const auto y = capsula::contour::extent(contour, 1);
    heightError.push_back(std::abs(y.max - y.min - 1.0));
    std::printf("  2a = 4, N = %3d: node extremes error %.3e, spline extremes error %.3e, "
                "height error %.3e\n",
                n, nodeError.back(), splineError.back(), heightError.back());
  }
  const double nodeOrder = fittedOrder(pointCounts, nodeError);
  const double splineOrder = fittedOrder(pointCounts, splineError);
  std::printf("  fitted orders: node extremes %.2f, spline extremes %.2f\n", nodeOrder, splineOrder);
  EXPECT_LT(nodeOrder, 2.2);
  EXPECT_GT(splineOrder, 3.7);
  EXPECT_GT(fittedOrder(pointCounts, heightError), 3.7);
}

} // namespace
