// Points found by property: the point at a given arc length, the extreme points of a spline.
#include "capsula/testing/Constants.hpp"
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/ContourLocation.hpp>
#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/contour/InitialShapes.hpp>
#include <capsula/core/Error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using capsula::testing::pi;

namespace {

using namespace capsula::contour;

} // namespace

TEST(ContourLocation, ArcLengthOnACircleGivesTheAngle)
{
  // Radius 2, node 0 at angle 0: the point at arc length l is 2 (cos(l/2), sin(l/2)) up to
  // the spline's O(h^4) position error (64 nodes: ~1e-7 relative), and its arc length by
  // the contour's own rule is l to round-off (that is what Newton solves).
  const Contour circle(circleNodes(64, 2.0));
  for (const double l : {0.0, 0.3, 3.0, 7.7, 12.5, circle.length() - 1e-3}) {
    const ContourLocation where = locateArcLength(circle, l);
    EXPECT_NEAR(circle.arcLengthAt(where.segment, where.t), l, 1e-12) << l;
    const Eigen::Vector2d p = circle.positionAt(where.segment, where.t);
    const double angle = l / circle.length() * 2.0 * pi;
    EXPECT_NEAR(p.x(), 2.0 * std::cos(angle), 1e-6) << l;
    EXPECT_NEAR(p.y(), 2.0 * std::sin(angle), 1e-6) << l;
  }
  // Periodic contours wrap: -1 and L - 1 are the same point.
  const ContourLocation a = locateArcLength(circle, -1.0);
  const ContourLocation b = locateArcLength(circle, circle.length() - 1.0);
  EXPECT_EQ(a.segment, b.segment);
  EXPECT_NEAR(a.t, b.t, 1e-12);
}

TEST(ContourLocation, LowestPointOfATiltedEllipseLiesBetweenNodes)
{
  // An ellipse a/b = 2 tilted by 0.4 rad: its lowest point is at the parametric angle
  // theta* with d/dtheta (a cos(phi) sin(theta) + b sin(phi)... ) = 0, i.e.
  // tan(theta*) = b cos(phi) / (a sin(phi)) on the lower side. With 40 nodes no node is
  // there, so the nodes' minimum misses it by O(h^2); the spline's is exact to O(h^4).
  EllipseShape shape;
  shape.aspectRatio = 2.0;
  shape.orientation = 0.4;
  const Contour ellipse(ellipseNodes(80, shape));
  const double a = std::sqrt(2.0), b = 1.0 / std::sqrt(2.0), phi = 0.4;
  // y(theta) = a cos(theta) sin(phi) + b sin(theta) cos(phi), minimal where
  // -a sin(theta) sin(phi) + b cos(theta) cos(phi) = 0.
  const double theta = std::atan2(b * std::cos(phi), a * std::sin(phi)) + pi;
  const double lowestY = a * std::cos(theta) * std::sin(phi) + b * std::sin(theta) * std::cos(phi);
  const ContourLocation lowest = lowestPoint(ellipse);
  const Eigen::Vector2d p = ellipse.positionAt(lowest.segment, lowest.t);
  EXPECT_NEAR(p.y(), lowestY, 1e-6); // the spline position error: 7e-6 at 40 nodes, 5e-7 at 80
  EXPECT_GT(lowest.t, 0.0);
  EXPECT_LT(lowest.t, 1.0);
  // ... where the tangent is horizontal.
  EXPECT_NEAR(ellipse.pointAt(lowest.segment, lowest.t).tangent.y(), 0.0, 1e-12);
  double lowestNode = 1e9;
  for (int i = 0; i < ellipse.numberOfNodes(); ++i) {
    lowestNode = std::min(lowestNode, ellipse.nodes()(1, i));
  }
  EXPECT_LT(p.y(), lowestNode);
}

TEST(ContourLocation, LargestPointIsTheSplineMaximumBetweenNodes)
{
  // The tilted ellipse above with 24 nodes: along either axis its largest point lies between
  // nodes, beyond every node, with the tangent normal to the axis, and its value is extent's.
  EllipseShape shape;
  shape.aspectRatio = 2.0;
  shape.orientation = 0.4;
  const Contour ellipse(ellipseNodes(24, shape));
  for (const int axis : {0, 1}) {
    const ContourExtremum largest = extremePoint(ellipse, axis, Extreme::Largest);
    const ContourLocation at = largest.location;
    EXPECT_EQ(largest.value, extent(ellipse, axis).max);
    EXPECT_EQ(extremePoint(ellipse, axis, Extreme::Smallest).value, extent(ellipse, axis).min);
    EXPECT_NEAR(ellipse.pointAt(at.segment, at.t).position[axis], largest.value, 1e-14);
    EXPECT_LT(std::abs(ellipse.pointAt(at.segment, at.t).tangent[axis]), 1e-10);
    double largestNode = -1e9;
    for (int i = 0; i < ellipse.numberOfNodes(); ++i) {
      largestNode = std::max(largestNode, ellipse.nodes()(axis, i));
    }
    EXPECT_GT(largest.value, largestNode);
  }
}

TEST(ContourLocation, ExtremePointRefusesAnAxisOtherThanXOrY)
{
  const Contour circle(circleNodes(16, 1.0, Eigen::Vector2d::Zero()));
  try {
    extremePoint(circle, 2, Extreme::Largest);
    FAIL() << "axis 2 was accepted";
  } catch (const capsula::core::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("axis must be 0 (x) or 1 (y), got 2"), std::string::npos) << error.what();
  }
}
