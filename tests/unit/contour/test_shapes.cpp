// Initial shapes (Fig. 4.1): equal-area ellipses, node placement and orientation.
#include "capsula/testing/Constants.hpp"
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/contour/InitialShapes.hpp>
#include <capsula/core/Error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using capsula::testing::pi;

namespace {

using capsula::contour::EllipseShape;
using capsula::contour::NodeSpacing;

TEST(ContourShapes, EllipseNodesLieOnTheEqualAreaEllipse)
{
  for (double ratio : {0.25, 0.5, 1.0, 3.0}) {
    EllipseShape shape;
    shape.aspectRatio = ratio;
    shape.lengthScale = 1.5;
    shape.centre = Eigen::Vector2d(1.0, 2.0);
    shape.orientation = -0.7;
    shape.firstNodeAngle = -0.5 * pi;
    const double a = 1.5 * std::sqrt(ratio), b = 1.5 / std::sqrt(ratio);
    EXPECT_NEAR(a * b, 1.5 * 1.5, 1e-14); // area pi L^2 for every aspect ratio
    for (NodeSpacing spacing : {NodeSpacing::EqualArcLength, NodeSpacing::EqualEllipseAngle}) {
      shape.spacing = spacing;
      const Eigen::Matrix2Xd nodes = capsula::contour::ellipseNodes(48, shape);
      for (int i = 0; i < nodes.cols(); ++i) {
        const Eigen::Vector2d d = nodes.col(i) - shape.centre;
        const double u = std::cos(0.7) * d.x() - std::sin(0.7) * d.y(); // rotate back by -(-0.7)
        const double v = std::sin(0.7) * d.x() + std::cos(0.7) * d.y();
        EXPECT_NEAR(u * u / (a * a) + v * v / (b * b), 1.0, 1e-13);
      }
      // Node 0 at theta = -pi/2: the end of the b-axis, (0, -b) in the body frame.
      const Eigen::Vector2d first = nodes.col(0) - shape.centre;
      EXPECT_NEAR(first.x(), b * std::sin(-0.7), 1e-13);
      EXPECT_NEAR(first.y(), -b * std::cos(-0.7), 1e-13);
      // Counter-clockwise: the Contour constructor would throw otherwise.
      const capsula::contour::Contour contour(nodes);
      // 48 nodes at a/b = 0.25: the spline area is within 1e-4 relative (metrics tests
      // check its convergence).
      EXPECT_NEAR(capsula::contour::enclosedArea(contour) / (pi * 1.5 * 1.5), 1.0, 1e-4);
    }
  }
}

TEST(ContourShapes, EqualArcLengthSpacing)
{
  EllipseShape shape;
  shape.aspectRatio = 0.25; // a = 0.5, b = 2
  shape.firstNodeAngle = 0.3;
  shape.spacing = NodeSpacing::EqualArcLength;
  const int n = 40;
  const Eigen::Matrix2Xd nodes = capsula::contour::ellipseNodes(n, shape);
  const double a = 0.5, b = 2.0;
  // Exact arc between consecutive nodes: recover theta and integrate the speed by a
  // 2000-interval Simpson rule (error ~1e-13 for this smooth integrand).
  auto arc = [&](double from, double to) {
    const int m = 2000;
    const double h = (to - from) / m;
    double sum = 0.0;
    for (int i = 0; i <= m; ++i) {
      const double t = from + i * h;
      const double w = (i == 0 || i == m) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      sum += w * std::hypot(a * std::sin(t), b * std::cos(t));
    }
    return sum * h / 3.0;
  };
  std::vector<double> theta(n + 1);
  for (int i = 0; i < n; ++i) {
    theta[i] = std::atan2(nodes(1, i) / b, nodes(0, i) / a);
    while (i > 0 && theta[i] <= theta[i - 1]) {
      theta[i] += 2.0 * pi;
    }
  }
  EXPECT_NEAR(theta[0], 0.3, 1e-14);
  theta[n] = theta[0] + 2.0 * pi;
  const double target = arc(0.0, 2.0 * pi) / n;
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(arc(theta[i], theta[i + 1]), target, 1e-11) << "between nodes " << i << ", " << i + 1;
  }
}

TEST(ContourShapes, CircleIsTheUnitAspectRatioEllipse)
{
  const Eigen::Matrix2Xd circle = capsula::contour::circleNodes(12, 2.0, {1.0, -1.0}, 0.3);
  for (int i = 0; i < 12; ++i) {
    const double angle = 0.3 + 2.0 * pi * i / 12.0;
    EXPECT_NEAR(circle(0, i), 1.0 + 2.0 * std::cos(angle), 1e-14);
    EXPECT_NEAR(circle(1, i), -1.0 + 2.0 * std::sin(angle), 1e-14);
  }
}

TEST(ContourShapes, RejectsBadParameters)
{
  using capsula::core::InputError;
  EllipseShape shape;
  EXPECT_THROW(capsula::contour::ellipseNodes(2, shape), InputError);
  shape.aspectRatio = 0.0;
  EXPECT_THROW(capsula::contour::ellipseNodes(16, shape), InputError);
  shape.aspectRatio = 1.0;
  shape.lengthScale = -1.0;
  EXPECT_THROW(capsula::contour::ellipseNodes(16, shape), InputError);
  EXPECT_THROW(capsula::contour::circleNodes(16, 0.0), InputError);
}

} // namespace
