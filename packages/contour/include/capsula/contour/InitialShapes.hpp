#pragma once
// Initial cell contours of the Chapter 4 study: circles and ellipses of equal area
// (thesis Fig. 4.1: semi-axes a, b with length scale L = sqrt(ab), so area pi L^2).
#include <Eigen/Core>

namespace capsula::contour {

/// How the marker points are spread along the ellipse. The thesis (A.3) does not say.
/// Equal steps of the parametric angle crowd the points towards the sharp ends (spacing
/// proportional to sqrt(a^2 sin^2 + b^2 cos^2)), where the curvature is highest: at
/// a/b = 0.25 and N = 128 the spline's position error is 1e-6 against 8e-5 with equal
/// arc lengths, hence the default.
enum class NodeSpacing {
  EqualEllipseAngle, ///< equal steps of the parametric angle theta in (a cos, b sin)
  EqualArcLength     ///< equal true arc length between consecutive nodes
};

struct EllipseShape {
  double aspectRatio = 1.0; ///< a/b: semi-axis a along `orientation`, b across it
  double lengthScale = 1.0; ///< L = sqrt(ab): a = L sqrt(a/b), b = L / sqrt(a/b)
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double orientation = 0.0;    ///< angle of the a-axis from the x-axis (radians)
  double firstNodeAngle = 0.0; ///< parametric angle theta of node 0 (-pi/2: the b-end below)
  NodeSpacing spacing = NodeSpacing::EqualEllipseAngle;
};

/// `numberOfNodes` points on the ellipse, counter-clockwise from node 0, without
/// repeating node 0: x = centre + R(orientation) (a cos theta, b sin theta).
/// Throws InputError for numberOfNodes < 3 or a non-positive aspect ratio or length scale.
Eigen::Matrix2Xd ellipseNodes(int numberOfNodes, const EllipseShape& shape);

/// Equally spaced points on a circle, counter-clockwise, node 0 at angle `firstNodeAngle`.
Eigen::Matrix2Xd circleNodes(int numberOfNodes, double radius, const Eigen::Vector2d& centre = Eigen::Vector2d::Zero(),
                             double firstNodeAngle = 0.0);

} // namespace capsula::contour
