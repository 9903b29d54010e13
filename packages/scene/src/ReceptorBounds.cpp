#include "capsula/scene/ReceptorBounds.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Measures.hpp>

#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cmath>

namespace capsula::scene {

namespace core = capsula::core;

namespace {

const char* const patchKey = "Adhesion/Patch radius";

// The distance between receptor r's material point and its pulling point.
double patchDepth(const adhesion::ReceptorSet& receptors, const mesh::SurfaceMesh& cell, const double* reference, int r)
{
  const adhesion::Receptor& point = receptors[r];
  const mesh::Vec3 surface = mesh::surfacePosition(cell.elementNodes(point.element, reference),
                                                   receptors.shapeParameters(point.element), point.xi, point.eta);
  return (receptors.position(cell, reference, r) - surface).norm();
}

// The depth of receptor r's pulling point with a patch of `radius` (0 where the patch holds
// too few quadrature points to be built: a patch that small lies within any reach).
double depthWithRadius(const adhesion::ReceptorSet& receptors, const mesh::SurfaceMesh& cell,
                       const std::vector<double>& reference, int r, double radius)
{
  adhesion::ReceptorSet one(cell, reference, {receptors[r]});
  try {
    one.spreadOverPatches(cell, reference, radius, patchKey);
  } catch (const core::InputError&) {
    return 0.0;
  }
  return patchDepth(one, cell, reference.data(), 0);
}

} // namespace

double receptorCapacity()
{
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  const double memory = pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 0.0;
  const double byIndex = static_cast<double>(INT_MAX);
  return memory > 0.0 ? std::min(byIndex, memory / static_cast<double>(kBytesPerReceptor)) : byIndex;
}

void requireReceptorsFit(const adhesion::AdhesionSettings& settings, const std::vector<mesh::SurfaceMesh>& cells,
                         const std::vector<std::vector<double>>& references)
{
  double area = 0.0;
  for (std::size_t c = 0; c < cells.size() && c < references.size(); ++c) {
    for (const double a : mesh::elementAreas(cells[c], references[c].data())) {
      area += a;
    }
  }
  const double count = settings.receptorDensity * area, capacity = receptorCapacity();
  core::require<core::InputError>(
      count <= capacity, "'Adhesion/Receptor density' = ", settings.receptorDensity, " puts about ", count,
      " receptors on the cells' ", area, " a^2 of membrane; at most ", capacity, " fit (in this machine's memory at ",
      kBytesPerReceptor, " bytes each, and in a receptor index). Give a density <= ", capacity / area, ".");
}

void requirePatchesWithinReach(const adhesion::AdhesionSettings& settings, const adhesion::ReceptorSet& receptors,
                               const mesh::SurfaceMesh& cell, const std::vector<double>& reference)
{
  if (!receptors.patched()) {
    return;
  }
  int deepest = -1;
  double depth = 0.0;
  for (int r = 0; r < receptors.size(); ++r) {
    const double d = patchDepth(receptors, cell, reference.data(), r);
    if (d > depth) {
      depth = d;
      deepest = r;
    }
  }
  // A membrane held by bonds at their rest length lambda puts the pulling point at lambda +
  // depth: within the reach r_0 only while depth < r_0 - lambda.
  const double reach = settings.reactionDistance - settings.equilibriumLength;
  if (depth < reach) {
    return;
  }
  // The widest radius whose pulling point stays within the reach, by bisection on the
  // deepest receptor (the depth grows with the radius: ~ rho^2 / (8 R) on a sphere).
  double inside = 0.0, outside = settings.patchRadius;
  for (int i = 0; i < 40; ++i) {
    const double middle = 0.5 * (inside + outside);
    (depthWithRadius(receptors, cell, reference, deepest, middle) < reach ? inside : outside) = middle;
  }
  throw core::InputError(core::message(
      "'", patchKey, "' = ", settings.patchRadius, " puts the pulling point of receptor ", deepest,
      " (the mean of its patch) ", depth,
      " a inside the unstressed membrane, more than 'Adhesion/Reaction distance' - 'Adhesion/Equilibrium length' = ",
      settings.reactionDistance, " - ", settings.equilibriumLength, " = ", reach,
      ": on a membrane held at the bonds' rest length it is out of reach, and it binds only where the membrane "
      "flattens over the patch's whole width. Give a radius below ",
      inside, " (0: point receptors)."));
}

} // namespace capsula::scene
