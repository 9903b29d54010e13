#include "capsula/contour/InitialShapes.hpp"

#include <capsula/quadrature/GaussLegendre.hpp>

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace capsula::contour {

namespace {

using core::InputError;
using core::require;

/// Arc length of the ellipse (a cos theta, b sin theta) as a function of theta:
/// a table of panel integrals plus Gauss-Legendre inside a panel, inverted by Newton.
class EllipseArcLength {
public:
  EllipseArcLength(double a, double b, double start) : a_(a), b_(b), start_(start), rule_(quadrature::gaussLegendre(16))
  {
    // The speed sqrt(a^2 sin^2 + b^2 cos^2) is analytic within atanh(min/max) of the real
    // axis; panels no wider than that distance make 16-point Gauss exact to round-off.
    const double pi = std::acos(-1.0);
    const double distance = std::atanh(std::min(a, b) / std::max(a, b));
    const double panels = std::max(64.0, std::ceil(2.0 * pi / distance));
    panelCount_ = static_cast<std::size_t>(panels);
    width_ = 2.0 * pi / panels;
    cumulative_.assign(panelCount_ + 1, 0.0);
    for (std::size_t j = 0; j < panelCount_; ++j) {
      cumulative_[j + 1] = cumulative_[j] + integral(edge(j), edge(j) + width_);
    }
  }

  double perimeter() const { return cumulative_.back(); }

  /// theta such that the arc length from `start` equals `target` (0 <= target < perimeter).
  double angleAt(double target) const
  {
    const auto above = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
    const std::size_t j =
        std::min(static_cast<std::size_t>(std::max<long>(above - cumulative_.begin() - 1, 0)), panelCount_ - 1);
    const double panelLength = cumulative_[j + 1] - cumulative_[j];
    double theta = edge(j) + width_ * (target - cumulative_[j]) / panelLength;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const double residual = cumulative_[j] + integral(edge(j), theta) - target;
      const double step = residual / speed(theta);
      theta -= step;
      if (std::abs(step) < 1e-15 * (1.0 + std::abs(theta))) {
        break;
      }
    }
    return theta;
  }

private:
  double speed(double theta) const { return std::hypot(a_ * std::sin(theta), b_ * std::cos(theta)); }

  double edge(std::size_t j) const { return start_ + static_cast<double>(j) * width_; }

  double integral(double from, double to) const
  {
    double sum = 0.0;
    for (std::size_t q = 0; q < rule_.points.size(); ++q) {
      sum += rule_.weights[q] * speed(from + (to - from) * rule_.points[q]);
    }
    return sum * (to - from);
  }

  double a_;
  double b_;
  double start_;
  quadrature::Rule1D rule_;
  std::size_t panelCount_ = 0;
  double width_ = 0.0;
  std::vector<double> cumulative_;
};

} // namespace

Eigen::Matrix2Xd ellipseNodes(int numberOfNodes, const EllipseShape& shape)
{
  require<InputError>(numberOfNodes >= 3, "an ellipse contour needs at least 3 nodes, got ", numberOfNodes);
  require<InputError>(std::isfinite(shape.aspectRatio) && shape.aspectRatio > 0.0,
                      "ellipse aspect ratio a/b must be positive, got ", shape.aspectRatio);
  require<InputError>(std::isfinite(shape.lengthScale) && shape.lengthScale > 0.0,
                      "ellipse length scale sqrt(ab) must be positive, got ", shape.lengthScale);
  require<InputError>(shape.centre.allFinite() && std::isfinite(shape.orientation) &&
                          std::isfinite(shape.firstNodeAngle),
                      "ellipse centre, orientation and first node angle must be finite");

  const double a = shape.lengthScale * std::sqrt(shape.aspectRatio);
  const double b = shape.lengthScale / std::sqrt(shape.aspectRatio);
  const double pi = std::acos(-1.0);
  std::vector<double> angles(static_cast<std::size_t>(numberOfNodes));
  if (shape.spacing == NodeSpacing::EqualEllipseAngle) {
    for (int i = 0; i < numberOfNodes; ++i) {
      angles[static_cast<std::size_t>(i)] = shape.firstNodeAngle + 2.0 * pi * i / numberOfNodes;
    }
  } else {
    const EllipseArcLength arc(a, b, shape.firstNodeAngle);
    for (int i = 0; i < numberOfNodes; ++i) {
      angles[static_cast<std::size_t>(i)] = arc.angleAt(arc.perimeter() * static_cast<double>(i) / numberOfNodes);
    }
  }

  const double c = std::cos(shape.orientation);
  const double s = std::sin(shape.orientation);
  Eigen::Matrix2Xd nodes(2, numberOfNodes);
  for (int i = 0; i < numberOfNodes; ++i) {
    const double theta = angles[static_cast<std::size_t>(i)];
    const double u = a * std::cos(theta);
    const double v = b * std::sin(theta);
    nodes(0, i) = shape.centre.x() + c * u - s * v;
    nodes(1, i) = shape.centre.y() + s * u + c * v;
  }
  return nodes;
}

Eigen::Matrix2Xd circleNodes(int numberOfNodes, double radius, const Eigen::Vector2d& centre, double firstNodeAngle)
{
  require<InputError>(std::isfinite(radius) && radius > 0.0, "circle radius must be positive, got ", radius);
  EllipseShape shape;
  shape.lengthScale = radius;
  shape.centre = centre;
  shape.firstNodeAngle = firstNodeAngle;
  shape.spacing = NodeSpacing::EqualEllipseAngle;
  return ellipseNodes(numberOfNodes, shape);
}

} // namespace capsula::contour
