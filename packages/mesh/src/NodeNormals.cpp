#include <capsula/mesh/NodeNormals.hpp>

#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Measures.hpp>

namespace capsula::mesh {

std::vector<Vec3> nodeNormals(const SurfaceMesh& mesh, const double* positions, int numQuadraturePoints)
{
  const std::vector<double> areas = elementAreas(mesh, positions, numQuadraturePoints);
  std::vector<Vec3> normals(mesh.numNodes(), Vec3::Zero());
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e, positions);
    const ShapeParameters p = shapeParameters(x);
    const double area = areas[e];
    for (int i = 0; i < 6; ++i) {
      const int node = mesh.element(e)[i];
      normals[node] += area * evaluateAtNode(x, p, i).normal;
    }
  }
  for (Vec3& n : normals) {
    n.normalize();
  }
  return normals;
}

std::vector<Vec3> nodeNormals(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  return nodeNormals(mesh, mesh.positionData(), numQuadraturePoints);
}

} // namespace capsula::mesh
