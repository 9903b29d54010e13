#include "capsula/scene/CellStability.hpp"

#include <capsula/mesh/MeshQuality.hpp>

#include <algorithm>

namespace capsula::scene {

double localElementSize(const mesh::SurfaceMesh& cell, int node)
{
  double size = 0.0;
  for (const auto& incidence : cell.incidentElements(node)) {
    const auto& element = cell.element(incidence.element);
    // Vertices are the first three nodes of an element (SurfaceMesh numbering).
    for (int k = 0; k < 3; ++k) {
      size = std::max(size, (cell.position(element[k]) - cell.position(element[(k + 1) % 3])).norm());
    }
  }
  return size;
}

CellStability measureStability(const mesh::SurfaceMesh& cell, const elasticity::MembraneMechanics& membrane)
{
  CellStability s;
  const mesh::MeshQuality quality = mesh::meshQuality(cell);
  s.minAngleDegrees = quality.minAngle;
  s.maxEdgeRatio = quality.maxEdgeRatio;
  s.maxDistortion = quality.maxDistortion;
  s.mostCompressiveTension = membrane.mostCompressiveTension().tension;
  s.minPrincipalStiffness = membrane.leastPrincipalStiffness().stiffness / membrane.law().shearModulus();
  int lowest = 0;
  for (int i = 1; i < cell.numNodes(); ++i) {
    if (cell.position(i)[1] < cell.position(lowest)[1]) {
      lowest = i;
    }
  }
  const double size = localElementSize(cell, lowest);
  s.wallGapPerElementSize = size > 0.0 ? cell.position(lowest)[1] / size : 0.0;
  return s;
}

} // namespace capsula::scene
