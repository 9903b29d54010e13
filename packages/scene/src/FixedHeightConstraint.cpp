#include "capsula/scene/FixedHeightConstraint.hpp"

#include "capsula/scene/CellKinematics.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::scene {

FixedHeightConstraint::FixedHeightConstraint(std::vector<mesh::SurfaceMesh> cells, std::vector<int> nodeOffsets)
    : cells_(std::move(cells)), nodeOffsets_(std::move(nodeOffsets))
{
  core::require(cells_.size() == nodeOffsets_.size(), "FixedHeightConstraint: ", cells_.size(), " cells but ",
                nodeOffsets_.size(), " node offsets");
}

void FixedHeightConstraint::apply(const std::vector<double>& positions, std::vector<double>& velocities)
{
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    mesh::SurfaceMesh& cell = cells_[k];
    const std::size_t first = 3 * static_cast<std::size_t>(nodeOffsets_[k]);
    core::require(first + 3 * static_cast<std::size_t>(cell.numNodes()) <= positions.size(),
                  "FixedHeightConstraint: the state is too short for cell ", k);
    cell.setPositions(positions.data() + first);
    const double rise = centroidVelocity(cell, velocities.data() + first)[1];
    for (int i = 0; i < cell.numNodes(); ++i) {
      velocities[first + 3 * static_cast<std::size_t>(i) + 1] -= rise;
    }
  }
}

} // namespace capsula::scene
