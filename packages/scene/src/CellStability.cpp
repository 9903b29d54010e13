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

MembraneExtremes membraneExtremes(const elasticity::MembraneMechanics& membrane)
{
  return {membrane.mostCompressiveTension().tension,
          membrane.leastPrincipalStiffness().stiffness / membrane.law().shearModulus()};
}

CellStability measureStability(const mesh::SurfaceMesh& cell, const elasticity::MembraneMechanics& membrane,
                               const domain::Domain& domain)
{
  return measureStability(cell, membraneExtremes(membrane), domain);
}

CellStability measureStability(const mesh::SurfaceMesh& cell, const MembraneExtremes& membrane,
                               const domain::Domain& domain)
{
  CellStability s;
  const mesh::MeshQuality quality = mesh::meshQuality(cell);
  s.minAngleDegrees = quality.minAngle;
  s.maxEdgeRatio = quality.maxEdgeRatio;
  s.maxDistortion = quality.maxDistortion;
  s.mostCompressiveTension = membrane.mostCompressiveTension;
  s.minPrincipalStiffness = membrane.leastPrincipalStiffness;
  // The gap of a node: its distance to the nearer wall, or its height without walls.
  const auto gapOf = [&](int node) {
    const mesh::Vec3& x = cell.position(node);
    const double point[3] = {x[0], x[1], x[2]};
    return domain.hasWalls() ? domain.distanceToNearestWall(point) : x[1];
  };
  int closest = 0;
  double gap = gapOf(0);
  for (int i = 1; i < cell.numNodes(); ++i) {
    const double g = gapOf(i);
    if (g < gap) {
      gap = g;
      closest = i;
    }
  }
  const double size = localElementSize(cell, closest);
  s.wallGapPerElementSize = size > 0.0 ? gap / size : 0.0;
  return s;
}

} // namespace capsula::scene
