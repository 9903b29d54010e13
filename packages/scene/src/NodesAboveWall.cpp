#include "capsula/scene/NodesAboveWall.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

namespace capsula::scene {

void requireNodesAboveWall(const Scene& scene, const std::vector<double>& positions)
{
  const SceneDescription& description = scene.description();
  if (!description.wall) {
    return;
  }
  for (int c = 0; c < scene.numCells(); ++c) {
    const std::size_t first = 3 * static_cast<std::size_t>(scene.nodeOffset(c));
    for (int i = 0; i < scene.cell(c).numNodes(); ++i) {
      const double y = positions[first + 3 * static_cast<std::size_t>(i) + 1];
      if (y > 0.0) { // NaN fails too
        continue;
      }
      const char* why = description.contact.enabled
                            ? "; the contact repulsion ('Contact/Strength', 'Contact/Range') did not hold it"
                            : "; the boundary-integral model has no contact force unless 'Contact/Enabled' is true";
      throw timeint::StateOutsideDomain(core::message("node ", i, " of '",
                                                      description.cells[static_cast<std::size_t>(c)].path,
                                                      "' reached the wall (y = ", y, ")", why));
    }
  }
}

} // namespace capsula::scene
