#pragma once
// Helpers of the 2D operator tests: contours, a serial communicator, and the observed
// order of convergence when the number of nodes doubles.
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/InitialShapes.hpp>

#include <Eigen/Core>
#include <Teuchos_DefaultSerialComm.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace capsula::operators::testing2d {

inline Teuchos::RCP<const Teuchos::Comm<int>> serialComm()
{
  return Teuchos::rcp(new Teuchos::SerialComm<int>);
}

inline contour::Contour circle(int nodes, double radius, const Eigen::Vector2d& centre)
{
  return contour::Contour(contour::circleNodes(nodes, radius, centre));
}

/// Ellipse of aspect ratio a/b and L = sqrt(ab) = 1.
inline contour::Contour ellipse(int nodes, double aspectRatio, const Eigen::Vector2d& centre,
                                contour::Closure closure = contour::Closure::Periodic)
{
  contour::EllipseShape shape;
  shape.aspectRatio = aspectRatio;
  shape.centre = centre;
  shape.firstNodeAngle = -M_PI / 2.0;
  contour::ContourOptions options;
  options.closure = closure;
  return contour::Contour(contour::ellipseNodes(nodes, shape), options);
}

/// Least-squares slope p of log2|error| = c - p log2(N): error ~ N^-p.
inline double observedOrder(const std::vector<int>& nodes, const std::vector<double>& errors)
{
  const double n = static_cast<double>(nodes.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const double x = std::log2(static_cast<double>(nodes[i]));
    const double y = std::log2(std::abs(errors[i]));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace capsula::operators::testing2d
