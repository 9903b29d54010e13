#pragma once
// The integration points of a 2D contour and the interpolation of nodal fields along it
// (thesis App. A.6.1, eq A.40).
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/CubicSpline.hpp>
#include <capsula/quadrature/Rule1D.hpp>

#include <Eigen/Core>

#include <vector>

namespace capsula::scene2d {

/// N_GL Gauss-Legendre points on every segment of a contour, segment by segment:
/// point p lies on segment p / N_GL at the local parameter t = rule.points[p % N_GL].
/// Positions, normals and arc-length weights w_q (s_{k+1} - s_k) h are kept in flat
/// arrays (2 per point) for the kernel loops.
class ContourQuadrature2D {
public:
  /// `unitRule` on [0, 1] (quadrature::gaussLegendre(n)).
  ContourQuadrature2D(const contour::Contour& contour, quadrature::Rule1D unitRule);

  int numberOfPoints() const { return static_cast<int>(weights_.size()); }
  int pointsPerSegment() const { return static_cast<int>(rule_.points.size()); }
  int segmentOf(int p) const { return p / pointsPerSegment(); }
  double parameterOf(int p) const { return rule_.points[static_cast<std::size_t>(p % pointsPerSegment())]; }
  const quadrature::Rule1D& rule() const { return rule_; }

  const contour::ContourPoint& point(int p) const { return points_[static_cast<std::size_t>(p)]; }
  /// x0, y0, x1, y1, ...
  const std::vector<double>& positions() const { return positions_; }
  /// Outward unit normals, 2 per point.
  const std::vector<double>& normals() const { return normals_; }
  /// dl of each point: w_q (s_{k+1} - s_k) h.
  const std::vector<double>& weights() const { return weights_; }

private:
  quadrature::Rule1D rule_;
  std::vector<contour::ContourPoint> points_;
  std::vector<double> positions_;
  std::vector<double> normals_;
  std::vector<double> weights_;
};

/// A vector field given at the nodes of a contour (2 values per node), interpolated along
/// it by cubic splines in the contour's own parameter with the contour's own end
/// conditions (periodic; natural at a tether). Positions are interpolated the same way,
/// so for the node velocities this is the exact velocity of the spline point (k, t).
class ContourField2D {
public:
  ContourField2D(const contour::Contour& contour, const double* nodalValues);

  Eigen::Vector2d at(int segment, double t) const;
  /// The spline of component c (0: x, 1: y) in the contour's parameter.
  const contour::CubicSpline& component(int c) const { return c == 0 ? x_ : y_; }

private:
  std::vector<double> knots_;
  contour::CubicSpline x_;
  contour::CubicSpline y_;
};

} // namespace capsula::scene2d
