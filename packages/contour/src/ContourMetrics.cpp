#include "capsula/contour/ContourMetrics.hpp"

#include "capsula/contour/ContourLocation.hpp"

#include <capsula/core/Error.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace capsula::contour {

namespace {

/// Degree <= 11 integrands on cubic pieces: 6 Gauss points integrate them exactly.
constexpr int exactPoints = 6;

} // namespace

double enclosedArea(const Contour& contour)
{
  return 0.5 * contour.integrate([](const ContourPoint& p, int,
                                    double) { return p.position.x() * p.tangent.y() - p.position.y() * p.tangent.x(); },
                                 exactPoints);
}

Eigen::Vector2d centroid(const Contour& contour)
{
  const double area = enclosedArea(contour);
  const Eigen::Vector2d moments = contour.integrate(
      [](const ContourPoint& p, int, double) {
        const Eigen::Vector2d& x = p.position;
        return Eigen::Vector2d(x.x() * x.x() * p.tangent.y(), -x.y() * x.y() * p.tangent.x());
      },
      exactPoints);
  return moments / (2.0 * area);
}

Eigen::Matrix2d secondMomentOfArea(const Contour& contour)
{
  const Eigen::Vector2d centre = centroid(contour);
  // Moments about the centroid directly, so a contour far from the origin loses nothing
  // to cancellation.
  const Eigen::Vector3d moments = contour.integrate(
      [&centre](const ContourPoint& p, int, double) {
        const double x = p.position.x() - centre.x();
        const double y = p.position.y() - centre.y();
        return Eigen::Vector3d(x * x * x * p.tangent.y() / 3.0, -y * y * y * p.tangent.x() / 3.0,
                               0.5 * x * x * y * p.tangent.y());
      },
      exactPoints);
  Eigen::Matrix2d j;
  j << moments(0), moments(2), moments(2), moments(1);
  return j;
}

EquivalentEllipse equivalentEllipse(const Contour& contour)
{
  const double area = enclosedArea(contour);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(secondMomentOfArea(contour));
  // Eigenvalues ascending: the last is the major axis.
  const Eigen::Vector2d lambda = solver.eigenvalues().cwiseMax(0.0);
  EquivalentEllipse ellipse;
  ellipse.majorSemiAxis = 2.0 * std::sqrt(lambda(1) / area);
  ellipse.minorSemiAxis = 2.0 * std::sqrt(lambda(0) / area);
  const Eigen::Vector2d axis = solver.eigenvectors().col(1);
  double angle = std::atan2(axis.y(), axis.x());
  const double pi = std::acos(-1.0);
  if (angle <= -0.5 * pi) {
    angle += pi;
  } else if (angle > 0.5 * pi) {
    angle -= pi;
  }
  ellipse.orientation = angle;
  return ellipse;
}

double taylorDeformation(const Contour& contour)
{
  const EquivalentEllipse ellipse = equivalentEllipse(contour);
  return (ellipse.majorSemiAxis - ellipse.minorSemiAxis) / (ellipse.majorSemiAxis + ellipse.minorSemiAxis);
}

Extent extent(const Contour& contour, int axis)
{
  return {extremePoint(contour, axis, Extreme::Smallest).value, extremePoint(contour, axis, Extreme::Largest).value};
}

double cellLength(const Contour& contour)
{
  const Extent x = extent(contour, 0);
  return x.max - x.min;
}

} // namespace capsula::contour
