// Contour geometry: orientation conventions, convergence of position, curvature and arc
// length under refinement, the tethered (natural-end) contour.
#include "capsula/testing/Constants.hpp"
#include "capsula/testing/ConvergenceOrder.hpp"
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/InitialShapes.hpp>
#include <capsula/core/Error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using capsula::testing::pi;

namespace {

using capsula::contour::Closure;
using capsula::contour::Contour;
using capsula::contour::ContourOptions;
using capsula::contour::ContourPoint;
using capsula::contour::Parametrisation;

using capsula::testing::fittedOrder;

const std::vector<int> refinements{16, 32, 64, 128, 256};

/// A smooth star r(theta) = 1 + eps cos(3 theta): concave between its lobes for eps = 0.3.
struct Star {
  double eps = 0.3;
  double r(double t) const { return 1.0 + eps * std::cos(3.0 * t); }
  double dr(double t) const { return -3.0 * eps * std::sin(3.0 * t); }
  double ddr(double t) const { return -9.0 * eps * std::cos(3.0 * t); }
  Eigen::Vector2d position(double t) const { return r(t) * Eigen::Vector2d(std::cos(t), std::sin(t)); }
  double curvature(double t) const
  {
    const double a = r(t), b = dr(t), c = ddr(t);
    return (a * a + 2.0 * b * b - a * c) / std::pow(a * a + b * b, 1.5);
  }
  Eigen::Matrix2Xd nodes(int n) const
  {
    Eigen::Matrix2Xd x(2, n);
    for (int i = 0; i < n; ++i) {
      x.col(i) = position(2.0 * pi * i / n);
    }
    return x;
  }
};

TEST(ContourGeometry, CircleConventions)
{
  const double radius = 1.3;
  const Eigen::Vector2d centre(0.2, -0.1);
  const Contour circle(capsula::contour::circleNodes(64, radius, centre, 0.1));
  for (int k = 0; k < circle.numberOfSegments(); ++k) {
    for (double t : {0.0, 0.37}) {
      const ContourPoint p = circle.pointAt(k, t);
      const Eigen::Vector2d radial = (p.position - centre).normalized();
      // Spline of a 64-gon: directions good to O(h^3) ~ 1e-5.
      EXPECT_NEAR(p.normal.dot(radial), 1.0, 1e-6) << "normal must point outward";
      EXPECT_NEAR(p.tangent.x() * radial.y() - p.tangent.y() * radial.x(), -1.0, 1e-6)
          << "tangent must run counter-clockwise";
      EXPECT_NEAR(p.curvature, 1.0 / radius, 1e-3) << "curvature must be +1/R";
      EXPECT_NEAR(p.tangent.norm(), 1.0, 1e-15);
      EXPECT_NEAR(p.tangent.dot(p.normal), 0.0, 1e-15);
    }
  }
}

TEST(ContourGeometry, PositionAtIsThePositionOfPointAt)
{
  // The position-only evaluation (the 2D layer potentials' bisection tests) evaluates the
  // same spline expressions: equal bit for bit, nodes and dyadic parameters included.
  const Contour circle(capsula::contour::circleNodes(32, 0.8, Eigen::Vector2d(0.1, 1.0), 0.3));
  for (int k = 0; k < circle.numberOfSegments(); ++k) {
    for (const double t : {0.0, 0.125, 0.5, 0.7, 1.0}) {
      EXPECT_EQ(circle.positionAt(k, t), circle.pointAt(k, t).position) << "segment " << k << ", t = " << t;
    }
  }
}

TEST(ContourGeometry, RejectsClockwiseDuplicateAndTooFewNodes)
{
  using capsula::core::InputError;
  Eigen::Matrix2Xd square(2, 4);
  square << 0, 1, 1, 0, 0, 0, 1, 1;
  EXPECT_NO_THROW(Contour{square});
  EXPECT_THROW(Contour(square.rowwise().reverse()), InputError);
  Eigen::Matrix2Xd duplicate(2, 5);
  duplicate << 0, 1, 1, 1, 0, 0, 0, 1, 1, 1;
  EXPECT_THROW(Contour{duplicate}, InputError);
  EXPECT_THROW(Contour(square.leftCols(2)), InputError);
}

TEST(ContourGeometry, PeriodicCirclePositionConvergesAtFourthOrder)
{
  const double radius = 1.3;
  std::vector<double> positionError, curvatureError, lengthError;
  for (int n : refinements) {
    const Contour circle(capsula::contour::circleNodes(n, radius, {0.2, -0.1}, 0.1));
    double worstPosition = 0.0, worstCurvature = 0.0;
    for (int k = 0; k < n; ++k) {
      for (int j = 0; j < 8; ++j) {
        const ContourPoint p = circle.pointAt(k, j / 8.0);
        worstPosition = std::max(worstPosition, std::abs((p.position - Eigen::Vector2d(0.2, -0.1)).norm() - radius));
        worstCurvature = std::max(worstCurvature, std::abs(p.curvature - 1.0 / radius));
      }
    }
    positionError.push_back(worstPosition);
    curvatureError.push_back(worstCurvature);
    lengthError.push_back(std::abs(circle.length() - 2.0 * pi * radius));
    std::printf("  circle N = %3d: max radial error %.3e, max curvature error %.3e, "
                "length error %.3e\n",
                n, worstPosition, worstCurvature, lengthError.back());
  }
  const double positionOrder = fittedOrder(refinements, positionError);
  const double curvatureOrder = fittedOrder(refinements, curvatureError);
  const double lengthOrder = fittedOrder(refinements, lengthError);
  std::printf("  fitted orders: position %.2f, curvature %.2f, length %.2f\n", positionOrder, curvatureOrder,
              lengthOrder);
  EXPECT_GT(positionOrder, 3.8);  // cubic splines interpolate at O(h^4)
  EXPECT_GT(curvatureOrder, 1.9); // second derivatives of a cubic spline: O(h^2)
  EXPECT_GT(lengthOrder, 3.8);
}

TEST(ContourGeometry, StarCurvatureConvergesIncludingConcaveParts)
{
  const Star star;
  // Three lobes with kappa from -1.6 to 4.5: the curvature is asymptotic from N = 64.
  const std::vector<int> starRefinements{64, 128, 256, 512};
  std::vector<double> curvatureError, positionError;
  for (int n : starRefinements) {
    const Contour contour(star.nodes(n));
    double worstCurvature = 0.0, worstPosition = 0.0;
    bool sawConcave = false;
    for (int k = 0; k < n; ++k) {
      for (int j = 0; j < 4; ++j) {
        const ContourPoint p = contour.pointAt(k, j / 4.0);
        // Nearest point of the exact curve, by Newton on the polar angle.
        double theta = std::atan2(p.position.y(), p.position.x());
        for (int it = 0; it < 20; ++it) {
          const Eigen::Vector2d d = star.position(theta) - p.position;
          const Eigen::Vector2d tangent(star.dr(theta) * std::cos(theta) - star.r(theta) * std::sin(theta),
                                        star.dr(theta) * std::sin(theta) + star.r(theta) * std::cos(theta));
          theta -= d.dot(tangent) / tangent.squaredNorm();
        }
        worstPosition = std::max(worstPosition, (star.position(theta) - p.position).norm());
        worstCurvature = std::max(worstCurvature, std::abs(p.curvature - star.curvature(theta)));
        sawConcave = sawConcave || p.curvature < 0.0;
      }
    }
    EXPECT_TRUE(sawConcave) << "the star is concave between its lobes: kappa < 0 there";
    curvatureError.push_back(worstCurvature);
    positionError.push_back(worstPosition);
    std::printf("  star N = %3d: max position error %.3e, max curvature error %.3e\n", n, worstPosition,
                worstCurvature);
  }
  const double positionOrder = fittedOrder(starRefinements, positionError);
  const double curvatureOrder = fittedOrder(starRefinements, curvatureError);
  std::printf("  fitted orders: position %.2f, curvature %.2f\n", positionOrder, curvatureOrder);
  EXPECT_GT(positionOrder, 3.7);
  EXPECT_GT(curvatureOrder, 1.9);
}

TEST(ContourGeometry, NodeIndexParametrisationAlsoConverges)
{
  // Eq A.14 (s_k = k) on an ellipse with uneven spacing: still O(h^4) in position.
  std::vector<double> error;
  capsula::contour::EllipseShape shape;
  shape.aspectRatio = 4.0;
  shape.spacing = capsula::contour::NodeSpacing::EqualEllipseAngle;
  const double a = 2.0, b = 0.5;
  ContourOptions options;
  options.parametrisation = Parametrisation::NodeIndex;
  for (int n : refinements) {
    const Contour contour(capsula::contour::ellipseNodes(n, shape), options);
    EXPECT_DOUBLE_EQ(contour.parameters()[1], 1.0);
    double worst = 0.0;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d x = contour.pointAt(k, 0.5).position;
      worst = std::max(worst, std::abs(std::hypot(x.x() / a, x.y() / b) - 1.0));
    }
    error.push_back(worst);
  }
  const double order = fittedOrder(refinements, error);
  std::printf("  node-index ellipse: error at N = 256 %.3e, order %.2f\n", error.back(), order);
  EXPECT_GT(order, 3.7);
}

TEST(ContourGeometry, ArcLengthIsTheSplineLength)
{
  const Star star;
  const Contour contour(star.nodes(24));
  // Brute force: a polyline of 4000 points per segment on the spline itself (chord error
  // ~ L kappa^2 h^2 / 24 ~ 1e-9).
  double polyline = 0.0;
  for (int k = 0; k < contour.numberOfSegments(); ++k) {
    double segment = 0.0;
    for (int j = 0; j < 4000; ++j) {
      segment += (contour.pointAt(k, (j + 1) / 4000.0).position - contour.pointAt(k, j / 4000.0).position).norm();
    }
    EXPECT_NEAR(contour.segmentLength(k), segment, 1e-8);
    EXPECT_NEAR(contour.arcLengthAt(k, 1.0), contour.knotArcLengths()[k + 1], 1e-14);
    polyline += segment;
  }
  EXPECT_NEAR(contour.length(), polyline, 1e-7);
  EXPECT_DOUBLE_EQ(contour.arcLengthAt(0, 0.0), 0.0);
}

TEST(ContourGeometry, PointAtParameterWrapsAndMatchesSegments)
{
  const Contour contour(Star{}.nodes(20));
  const std::vector<double>& s = contour.parameters();
  const double period = s.back();
  const ContourPoint a = contour.pointAt(7, 0.25);
  const double s7 = s[7] + 0.25 * (s[8] - s[7]);
  for (double shift : {0.0, period, -2.0 * period}) {
    const ContourPoint b = contour.pointAtParameter(s7 + shift);
    EXPECT_NEAR((a.position - b.position).norm(), 0.0, 1e-12);
    EXPECT_NEAR(a.curvature, b.curvature, 1e-10);
  }
}

TEST(ContourGeometry, TetheredContourHasNaturalEndsAtTheTether)
{
  // Chapter 4: s = 0 at the tether (node 0), anticlockwise back to it at s_max.
  ContourOptions tethered;
  tethered.closure = Closure::Tethered;
  std::vector<double> endError, middleError;
  for (int n : refinements) {
    const Contour circle(capsula::contour::circleNodes(n, 1.0, {0.0, 1.0}, -0.5 * pi), tethered);
    const ContourPoint start = circle.pointAt(0, 0.0);
    const ContourPoint end = circle.pointAt(n - 1, 1.0);
    EXPECT_NEAR((start.position - end.position).norm(), 0.0, 1e-14);
    EXPECT_NEAR(start.curvature, 0.0, 1e-12); // eq A.31
    EXPECT_NEAR(end.curvature, 0.0, 1e-12);   // eq A.32
    double worstEnd = 0.0, worstMiddle = 0.0;
    for (int k = 0; k < n; ++k) {
      const double radial = std::abs((circle.pointAt(k, 0.5).position - Eigen::Vector2d(0.0, 1.0)).norm() - 1.0);
      if (k < n / 4 || k >= 3 * n / 4) {
        worstEnd = std::max(worstEnd, radial);
      } else {
        worstMiddle = std::max(worstMiddle, radial);
      }
    }
    endError.push_back(worstEnd);
    middleError.push_back(worstMiddle);
    std::printf("  tethered circle N = %3d: radial error near tether %.3e, far from it %.3e\n", n, worstEnd,
                worstMiddle);
  }
  // The zero-curvature ends cost accuracy near the tether only: O(h^2) there, while the
  // end effect decays geometrically away from it, leaving O(h^4) far from it.
  const double endOrder = fittedOrder(refinements, endError);
  const double middleOrder = fittedOrder(refinements, middleError);
  std::printf("  fitted orders: near tether %.2f, far %.2f\n", endOrder, middleOrder);
  EXPECT_GT(endOrder, 1.9);
  EXPECT_GT(middleOrder, 3.8);
}

} // namespace
