#include "capsula/scene/CellMetrics.hpp"

#include <capsula/mesh/EquivalentEllipsoid.hpp>
#include <capsula/mesh/Measures.hpp>

#include <algorithm>

namespace capsula::scene {

CellShape measureShape(const mesh::SurfaceMesh& cell)
{
  CellShape shape;
  shape.volume = mesh::enclosedVolume(cell, 6);
  shape.area = mesh::surfaceArea(cell, 7);
  shape.reducedVolume = mesh::reducedVolume(shape.area, shape.volume);
  shape.centroid = mesh::centroid(cell, 12);
  shape.deformation = shearDeformation(mesh::equivalentEllipsoid(cell, 13));
  shape.footprintXZ = mesh::projectedAreas(cell, 7)[1];
  return shape;
}

MembraneStress membraneStress(const mesh::SurfaceMesh& cell, const double* elementLoads)
{
  const std::vector<double> areas = mesh::elementAreas(cell, 7);
  MembraneStress stress;
  double total = 0.0;
  for (int e = 0; e < cell.numElements(); ++e) {
    const double magnitude = mesh::nodeAt(elementLoads, e).norm();
    stress.mean += areas[static_cast<std::size_t>(e)] * magnitude;
    stress.maximum = std::max(stress.maximum, magnitude);
    total += areas[static_cast<std::size_t>(e)];
  }
  stress.mean /= total;
  return stress;
}

} // namespace capsula::scene
