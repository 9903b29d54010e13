#include "capsula/scene/NodesAboveWall.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

namespace capsula::scene {

std::string nearestWallName(const domain::Domain& domain, const double* x)
{
  int nearest = -1;
  domain.distanceToNearestWall(x, &nearest);
  return nearest >= 0 && domain.walls()[static_cast<std::size_t>(nearest)].fluidSide < 0 ? "the upper wall"
                                                                                         : "the wall";
}

void requireNodesAboveWall(const Scene& scene, const std::vector<double>& positions)
{
  const SceneDescription& description = scene.description();
  if (!description.domain.hasWalls()) {
    return;
  }
  for (int c = 0; c < scene.numCells(); ++c) {
    const std::size_t first = 3 * static_cast<std::size_t>(scene.nodeOffset(c));
    for (int i = 0; i < scene.cell(c).numNodes(); ++i) {
      const double* x = positions.data() + first + 3 * static_cast<std::size_t>(i);
      if (description.domain.inFluid(x)) { // NaN fails
        continue;
      }
      const char* why = description.contact.enabled
                            ? "; the contact repulsion ('Contact/Strength', 'Contact/Range') did not hold it"
                            : "; the boundary-integral model has no contact force unless 'Contact/Enabled' is true";
      throw timeint::StateOutsideDomain(
          core::message("node ", i, " of '", description.cells[static_cast<std::size_t>(c)].path, "' reached ",
                        nearestWallName(description.domain, x), " (y = ", x[1], ")", why));
    }
  }
}

} // namespace capsula::scene
