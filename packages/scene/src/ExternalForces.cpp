#include "capsula/scene/ExternalForces.hpp"

#include <capsula/adhesion/ContactRepulsion.hpp>

#include <algorithm>
#include <sstream>

namespace capsula::scene {

ExternalForces::ExternalForces(const SceneDescription& description, const std::vector<mesh::SurfaceMesh>& cells,
                               const std::vector<std::vector<double>>& references)
    : wall_(description.wall), contact_(description.contact)
{
  if (description.adhesion.enabled) {
    bonds_.emplace(description.adhesion, cells, references);
    terms_.push_back(bonds_->describe());
  }
  if (description.tether.enabled) {
    const auto c = static_cast<std::size_t>(description.tether.cell);
    tether_.emplace(description.tether, cells[c], cells[c].positionData(), references[c], "Tether");
    terms_.push_back(tether_->describe());
  }
  if (contact_.enabled) {
    std::ostringstream line;
    line << "contact repulsion (" << (wall_ ? "wall and " : "") << "cells): range " << contact_.range << " a, strength "
         << contact_.strength << " G/a";
    terms_.push_back(line.str());
  }
  if (bonds_ || tether_ || contact_.enabled) {
    for (const mesh::SurfaceMesh& cell : cells) {
      forces_.emplace_back(3 * static_cast<std::size_t>(cell.numNodes()), 0.0);
    }
  }
}

void ExternalForces::compute(const std::vector<mesh::SurfaceMesh>& cells)
{
  for (auto& forces : forces_) {
    std::fill(forces.begin(), forces.end(), 0.0);
  }
  // The bonds as they are (frozen over the stages), spread onto the nodes by virtual work.
  if (bonds_) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      bonds_->addNodalForces(static_cast<int>(c), cells[c], cells[c].positionData(), forces_[c].data());
    }
  }
  if (tether_) {
    const auto c = static_cast<std::size_t>(tether_->cell());
    tether_->addNodalForces(cells[c], cells[c].positionData(), forces_[c].data());
  }
  if (!contact_.enabled) {
    return;
  }
  // The repulsion of the wall and of the other cells on each membrane (adhesion
  // ContactRepulsion.hpp), as physical nodal forces on it.
  for (std::size_t c = 0; c < cells.size() && wall_; ++c) {
    adhesion::addWallContactForces(contact_, cells[c], cells[c].positionData(), forces_[c].data());
  }
  for (std::size_t a = 0; a < cells.size(); ++a) {
    for (std::size_t b = a + 1; b < cells.size(); ++b) {
      adhesion::addCellContactForces(contact_, cells[a], cells[a].positionData(), forces_[a].data(), cells[b],
                                     cells[b].positionData(), forces_[b].data());
    }
  }
}

} // namespace capsula::scene
