// Element averaging (thesis Sections 3.5.2 and 5.5): each element's quadratic map gives
// its own curvature at a shared node (the surface is only C0 there); average them with
// the element areas as weights, as the node normals are.
#include <capsula/mesh/Curvature.hpp>

#include <capsula/mesh/ElementCurvature.hpp>
#include <capsula/mesh/Measures.hpp>

namespace capsula::mesh {

NodeCurvatures elementAveragedCurvature(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  const auto numNodes = static_cast<std::size_t>(mesh.numNodes());
  const std::vector<double> areas = elementAreas(mesh, numQuadraturePoints);
  NodeCurvatures result{std::vector<double>(numNodes, 0.0), std::vector<double>(numNodes, 0.0),
                        std::vector<Vec3>(numNodes, Vec3::Zero())};
  std::vector<double> weight(numNodes, 0.0);
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e);
    const ShapeParameters p = shapeParameters(x);
    const double area = areas[static_cast<std::size_t>(e)];
    for (int i = 0; i < 6; ++i) {
      const auto node = static_cast<std::size_t>(mesh.element(e)[static_cast<std::size_t>(i)]);
      const CurvedSurfacePoint s = evaluateCurvatureAtNode(x, p, i);
      result.mean[node] += area * s.mean;
      result.gaussian[node] += area * s.gaussian;
      result.normal[node] += area * s.normal;
      weight[node] += area;
    }
  }
  for (std::size_t node = 0; node < numNodes; ++node) {
    result.mean[node] /= weight[node];
    result.gaussian[node] /= weight[node];
    result.normal[node].normalize();
  }
  return result;
}

} // namespace capsula::mesh
