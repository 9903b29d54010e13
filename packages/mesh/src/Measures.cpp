#include <capsula/mesh/Measures.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/mesh/SurfaceIntegral.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <cmath>

namespace capsula::mesh {

std::vector<double> elementAreas(const SurfaceMesh& mesh, const double* positions, int numQuadraturePoints)
{
  const auto& rule = quadrature::triangleRule(numQuadraturePoints);
  std::vector<double> areas(mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e, positions);
    areas[e] = integrateOverElement(
        x, shapeParameters(x), rule, [](const SurfacePoint&) { return 1.0; }, 0.0);
  }
  return areas;
}

std::vector<double> elementAreas(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  return elementAreas(mesh, mesh.positionData(), numQuadraturePoints);
}

double surfaceArea(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  return integrateOverSurface(
      mesh, quadrature::triangleRule(numQuadraturePoints), [](const SurfacePoint&) { return 1.0; }, 0.0);
}

double enclosedVolume(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  return integrateOverSurface(
      mesh, quadrature::triangleRule(numQuadraturePoints),
      [](const SurfacePoint& s) { return s.position.dot(s.normal) / 3.0; }, 0.0);
}

Vec3 centroid(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  const auto& rule = quadrature::triangleRule(numQuadraturePoints);
  const double volume = enclosedVolume(mesh, numQuadraturePoints);
  core::require<core::NumericalError>(volume > 0.0, "centroid: the enclosed volume is ", volume,
                                      "; the surface is inverted or degenerate");
  const Vec3 moment = integrateOverSurface(
      mesh, rule,
      [](const SurfacePoint& s) -> Vec3 { return s.position.cwiseProduct(s.position).cwiseProduct(s.normal); },
      Vec3(Vec3::Zero()));
  return moment / (2.0 * volume);
}

double reducedVolume(double area, double volume)
{
  const double pi = std::acos(-1.0);
  return 6.0 * std::sqrt(pi) * volume / std::pow(area, 1.5);
}

double reducedVolume(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  return reducedVolume(surfaceArea(mesh, numQuadraturePoints), enclosedVolume(mesh, numQuadraturePoints));
}

Vec3 projectedAreas(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  return integrateOverSurface(
      mesh, quadrature::triangleRule(numQuadraturePoints),
      [](const SurfacePoint& s) -> Vec3 { return 0.5 * s.normal.cwiseAbs(); }, Vec3(Vec3::Zero()));
}

} // namespace capsula::mesh
