#pragma once
// Helpers of the 2D operator tests: contours and a serial communicator.
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/InitialShapes.hpp>

#include <Eigen/Core>
#include <Teuchos_DefaultSerialComm.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace capsula::scene2d::testing2d {

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

} // namespace capsula::scene2d::testing2d
