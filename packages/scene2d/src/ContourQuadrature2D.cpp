#include "capsula/scene2d/ContourQuadrature2D.hpp"

#include <cstddef>
#include <utility>

namespace capsula::scene2d {

ContourQuadrature2D::ContourQuadrature2D(const contour::Contour& contour, quadrature::Rule1D unitRule)
    : rule_(std::move(unitRule))
{
  const int segments = contour.numberOfSegments();
  const auto perSegment = rule_.points.size();
  const std::size_t n = static_cast<std::size_t>(segments) * perSegment;
  points_.reserve(n);
  positions_.reserve(2 * n);
  normals_.reserve(2 * n);
  weights_.reserve(n);
  const std::vector<double>& s = contour.parameters();
  for (int k = 0; k < segments; ++k) {
    const double span = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
    for (std::size_t q = 0; q < perSegment; ++q) {
      const contour::ContourPoint point = contour.pointAt(k, rule_.points[q]);
      positions_.push_back(point.position.x());
      positions_.push_back(point.position.y());
      normals_.push_back(point.normal.x());
      normals_.push_back(point.normal.y());
      weights_.push_back(rule_.weights[q] * span * point.metric);
      points_.push_back(point);
    }
  }
}

namespace {

contour::CubicSpline fitComponent(const contour::Contour& contour, const double* values, int component)
{
  const int n = contour.numberOfNodes();
  std::vector<double> nodal(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    nodal[static_cast<std::size_t>(i)] = values[2 * i + component];
  }
  if (contour.closure() == contour::Closure::Periodic) {
    return contour::CubicSpline::periodic(contour.parameters(), nodal);
  }
  nodal.push_back(values[component]); // the contour ends at the tether node again
  return contour::CubicSpline::natural(contour.parameters(), nodal);
}

} // namespace

ContourField2D::ContourField2D(const contour::Contour& contour, const double* nodalValues)
    : knots_(contour.parameters()), x_(fitComponent(contour, nodalValues, 0)), y_(fitComponent(contour, nodalValues, 1))
{}

Eigen::Vector2d ContourField2D::at(int segment, double t) const
{
  const auto k = static_cast<std::size_t>(segment);
  const double ds = t * (knots_[k + 1] - knots_[k]);
  return {x_.piece(segment).value(ds), y_.piece(segment).value(ds)};
}

} // namespace capsula::scene2d
