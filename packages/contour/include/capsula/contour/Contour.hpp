#pragma once
// A cell contour in the plane: N marker points joined by cubic splines x(s), y(s)
// in a monotonic parameter s (thesis App. A.3).
//
// Conventions (pinned by tests/unit/contour):
//   - Nodes run counter-clockwise (the constructor checks it). s increases along them
//     and the segment k joins node k to node k+1; the last segment returns to node 0.
//   - Tangent t = (dx/ds) / h with the metric h = |dx/ds| = dl/ds (eq A.28).
//   - Normal n = (t_y, -t_x): the tangent turned clockwise, i.e. pointing into the
//     exterior fluid for a counter-clockwise contour. (Eqs A.26-A.27 print the normal on
//     the left of increasing s, outward only for a clockwise s, while Fig. 4.22 runs s
//     anticlockwise; the solver needs n outward, eq A.4, and that is what is fixed here.)
//   - Curvature kappa = (x' y'' - y' x'') / h^3, so that dt/dl = -kappa n and a circle of
//     radius R has kappa = 1/R; kappa < 0 where the contour is locally concave.
//   - Closure::Periodic: a free cell, periodic end conditions (A.33-A.34).
//     Closure::Tethered: the cell of Chapter 4, whose spline parameter starts at the
//     tether point (node 0), runs anticlockwise and returns to it at s_max (thesis
//     Fig. 4.22). The spline is open there, so the tangent may turn at node 0. Its end
//     conditions (TetherEnds): natural, x'' = y'' = 0 (A.31-A.32: zero curvature at the
//     tether), or not-a-knot (x''' continuous at s_1 and s_{N-1}). Natural ends put an
//     O(h kappa) error into the tangents at the tether wherever the branches are curved
//     there (the membrane's normal balance gives kappa = (Delta f . n) / gamma, not 0), so
//     the tether force gamma t(0+) - gamma t(s_max-) is only first-order accurate; with
//     not-a-knot ends it is third-order (tests/unit/scene2d, Tension2DLoad). Per-node values
//     of node 0 are then the limits from segment 0 (s -> 0+); the other side is
//     pointAt(numberOfSegments() - 1, 1.0).
#include "capsula/contour/CubicSpline.hpp"
#include <capsula/quadrature/GaussLegendre.hpp>

#include <Eigen/Core>

#include <type_traits>
#include <utility>
#include <vector>

namespace capsula::contour {

enum class Closure { Periodic, Tethered };

/// End conditions of a tethered contour's position splines at the tether node.
enum class TetherEnds { Natural, NotAKnot };

/// The monotonic spline parameter (eq A.14 uses the node index; the cumulative chord
/// length keeps |dx/ds| close to 1 when the markers are unevenly spaced).
enum class Parametrisation { ChordLength, NodeIndex };

struct ContourOptions {
  Closure closure = Closure::Periodic;
  Parametrisation parametrisation = Parametrisation::ChordLength;
  /// Only for Closure::Tethered: natural is the thesis's A.31-A.32.
  TetherEnds tetherEnds = TetherEnds::Natural;
  /// Gauss-Legendre points per segment for arc lengths (|dx/ds| is not a polynomial).
  int arcLengthPoints = 8;
};

/// Local geometry at one point of a contour.
struct ContourPoint {
  Eigen::Vector2d position;
  Eigen::Vector2d derivative;       ///< dx/ds
  Eigen::Vector2d secondDerivative; ///< d2x/ds2
  double metric = 0.0;              ///< h = |dx/ds| = dl/ds (eq A.28)
  Eigen::Vector2d tangent;          ///< dx/dl
  Eigen::Vector2d normal;           ///< outward for a counter-clockwise contour
  double curvature = 0.0;           ///< 1/R on a circle of radius R
};

/// Tangent, normal, metric and curvature from the parametric derivatives (the kernel).
inline ContourPoint contourPoint(const Eigen::Vector2d& position, const Eigen::Vector2d& first,
                                 const Eigen::Vector2d& second)
{
  ContourPoint point;
  point.position = position;
  point.derivative = first;
  point.secondDerivative = second;
  point.metric = first.norm();
  point.tangent = first / point.metric;
  point.normal = Eigen::Vector2d(point.tangent.y(), -point.tangent.x());
  point.curvature = (first.x() * second.y() - first.y() * second.x()) / (point.metric * point.metric * point.metric);
  return point;
}

class Contour {
public:
  /// `nodes` holds one marker point per column, counter-clockwise, without repeating
  /// the first one at the end. Throws InputError for fewer than 3 nodes, non-finite or
  /// coincident consecutive nodes, or a clockwise polygon.
  explicit Contour(Eigen::Matrix2Xd nodes, ContourOptions options = {});

  int numberOfNodes() const { return static_cast<int>(nodes_.cols()); }
  /// Equal to numberOfNodes(): the last segment closes the contour.
  int numberOfSegments() const { return static_cast<int>(nodes_.cols()); }
  const Eigen::Matrix2Xd& nodes() const { return nodes_; }
  const ContourOptions& options() const { return options_; }
  Closure closure() const { return options_.closure; }

  /// Knots s_0 = 0 < s_1 < ... < s_N = s_max (N + 1 values; s_N is node 0 again).
  const std::vector<double>& parameters() const { return xSpline_.knots(); }
  const CubicSpline& xSpline() const { return xSpline_; }
  const CubicSpline& ySpline() const { return ySpline_; }

  /// Geometry on segment k at s = s_k + t (s_{k+1} - s_k), t in [0, 1].
  ContourPoint pointAt(int segment, double t) const;
  /// Only the position of pointAt(segment, t) (the same value, without the derivatives).
  Eigen::Vector2d positionAt(int segment, double t) const;
  /// Geometry at any parameter value (periodic contours wrap s; tethered ones clamp
  /// the segment to the end pieces).
  ContourPoint pointAtParameter(double s) const;
  /// Geometry at node i (for a tethered contour's node 0: the limit from segment 0).
  ContourPoint nodePoint(int i) const { return pointAt(i, 0.0); }

  Eigen::Matrix2Xd tangents() const;
  Eigen::Matrix2Xd normals() const;
  Eigen::VectorXd curvatures() const;

  /// True arc length of segment k (Gauss-Legendre on the spline, eq A.40).
  double segmentLength(int k) const { return segmentLengths_[static_cast<std::size_t>(k)]; }
  /// Arc length from node 0 to each knot: l_0 = 0, ..., l_N = length() (N + 1 values).
  const std::vector<double>& knotArcLengths() const { return knotArcLengths_; }
  double length() const { return knotArcLengths_.back(); }
  /// Arc length from node 0 to the point (segment k, t).
  double arcLengthAt(int segment, double t) const;

  /// Sum over segments of the Gauss-Legendre approximation (`points` per segment) of
  /// int f dl, where f(const ContourPoint&, int segment, double t) returns a double or
  /// a plain fixed-size Eigen object (Eigen::Vector2d, not an expression).
  template <typename Integrand>
  auto integrate(Integrand&& integrand, int points) const;

private:
  Eigen::Vector2d chord(int k) const;

  Eigen::Matrix2Xd nodes_;
  ContourOptions options_;
  CubicSpline xSpline_;
  CubicSpline ySpline_;
  quadrature::Rule1D arcLengthRule_;
  std::vector<double> segmentLengths_;
  std::vector<double> knotArcLengths_;
};

template <typename Integrand>
auto Contour::integrate(Integrand&& integrand, int points) const
{
  const quadrature::Rule1D rule = quadrature::gaussLegendre(points);
  using Result = std::decay_t<decltype(integrand(std::declval<const ContourPoint&>(), 0, 0.0))>;
  Result total{};
  bool first = true;
  const std::vector<double>& s = parameters();
  for (int k = 0; k < numberOfSegments(); ++k) {
    const double span = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const ContourPoint point = pointAt(k, rule.points[q]);
      const double weight = rule.weights[q] * span * point.metric;
      if (first) {
        total = integrand(point, k, rule.points[q]) * weight;
        first = false;
      } else {
        total += integrand(point, k, rule.points[q]) * weight;
      }
    }
  }
  return total;
}

} // namespace capsula::contour
