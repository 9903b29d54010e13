#include <capsula/mesh/MeshQuality.hpp>

#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/ShapeFunctions.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace capsula::mesh {

ElementQuality elementQuality(const SurfaceMesh& mesh, int element)
{
  const ElementNodes x = mesh.elementNodes(element);
  const double degreesPerRadian = 180.0 / std::acos(-1.0);
  ElementQuality q{std::numeric_limits<double>::infinity(), 0.0, 0.0, 0.0};
  double shortest = std::numeric_limits<double>::infinity();
  double longest = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Vec3& corner = x[k];
    const Vec3 toNext = x[(k + 1) % 3] - corner;
    const Vec3 toPrevious = x[(k + 2) % 3] - corner;
    // atan2(|a x b|, a . b) is accurate for angles near 0 and 180 degrees, unlike acos.
    const double angle = std::atan2(toNext.cross(toPrevious).norm(), toNext.dot(toPrevious)) * degreesPerRadian;
    q.minAngle = std::min(q.minAngle, angle);
    q.maxAngle = std::max(q.maxAngle, angle);
    shortest = std::min(shortest, toNext.norm());
    longest = std::max(longest, toNext.norm());
  }
  q.edgeRatio = longest / shortest;
  const ShapeParameters p = shapeParameters(x);
  q.distortion = std::max({std::abs(p.alpha - 0.5), std::abs(p.beta - 0.5), std::abs(p.gamma - 0.5)});
  return q;
}

MeshQuality meshQuality(const SurfaceMesh& mesh)
{
  MeshQuality summary{std::numeric_limits<double>::infinity(), 0.0, 1.0, 0.0};
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementQuality q = elementQuality(mesh, e);
    summary.minAngle = std::min(summary.minAngle, q.minAngle);
    summary.maxAngle = std::max(summary.maxAngle, q.maxAngle);
    summary.maxEdgeRatio = std::max(summary.maxEdgeRatio, q.edgeRatio);
    summary.maxDistortion = std::max(summary.maxDistortion, q.distortion);
  }
  return summary;
}

} // namespace capsula::mesh
