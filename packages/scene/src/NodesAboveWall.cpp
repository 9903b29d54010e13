#include "capsula/scene/NodesAboveWall.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

namespace capsula::scene {

void requireNodesAboveWall(const Scene& scene, const std::vector<double>& positions)
{
  const SceneDescription& description = scene.description();
  if (!description.domain.hasWalls()) {
    return;
  }
  for (int c = 0; c < scene.numCells(); ++c) {
    const double* cell = positions.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c));
    const int i = description.domain.firstPointOutsideFluid(cell, scene.cell(c).numNodes(), 3);
    if (i < 0) {
      continue;
    }
    const double* x = cell + 3 * static_cast<std::size_t>(i);
    const char* why = description.contact.enabled
                          ? "; the contact repulsion ('Contact/Strength', 'Contact/Range') did not hold it"
                          : "; the boundary-integral model has no contact force unless 'Contact/Enabled' is true";
    throw timeint::StateOutsideDomain(
        core::message("node ", i, " of '", description.cells[static_cast<std::size_t>(c)].path, "' reached ",
                      description.domain.nearestWallName(x[1]), " (y = ", x[1], ")", why));
  }
}

} // namespace capsula::scene
