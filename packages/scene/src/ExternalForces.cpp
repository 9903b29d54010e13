#include "capsula/scene/ExternalForces.hpp"

#include <capsula/adhesion/ContactRepulsion.hpp>

#include <algorithm>
#include <array>
#include <sstream>

namespace capsula::scene {

ExternalForces::ExternalForces(const SceneDescription& description, const std::vector<mesh::SurfaceMesh>& cells,
                               const std::vector<std::vector<double>>& references)
    : domain_(description.domain), walls_(contactWalls(description.domain)), contact_(description.contact)
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
    line << "contact repulsion ("
         << (walls_.empty()       ? ""
             : walls_.size() == 1 ? "wall and "
                                  : "walls and ")
         << "cells): range " << contact_.range << " a, strength " << contact_.strength << " G/a";
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
  // The repulsion of the walls and of the other cells on each membrane (adhesion
  // ContactRepulsion.hpp), as physical nodal forces on it.
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (const adhesion::ContactWall& wall : walls_) {
      adhesion::addWallContactForces(contact_, cells[c], cells[c].positionData(), forces_[c].data(), wall);
    }
  }
  // In a periodic domain each pair meets as its nearest images: cell b is moved by the
  // lattice vector that brings its node centre nearest to a's (the forces do not change
  // under a translation). The placement keeps every period longer than a cell and the
  // contact range, so no pair touches through two images at once.
  std::vector<std::array<double, 3>> centres;
  if (domain_.isPeriodic()) {
    for (const mesh::SurfaceMesh& cell : cells) {
      centres.push_back(nodeCentre(cell));
    }
  }
  std::vector<double> moved;
  for (std::size_t a = 0; a < cells.size(); ++a) {
    for (std::size_t b = a + 1; b < cells.size(); ++b) {
      const double* xb = cells[b].positionData();
      if (!centres.empty()) {
        const std::array<double, 3> shift = imageShift(centres[a], centres[b]);
        if (shift[0] != 0.0 || shift[2] != 0.0) {
          moved.assign(xb, xb + 3 * static_cast<std::size_t>(cells[b].numNodes()));
          for (std::size_t k = 0; k < moved.size(); ++k) {
            moved[k] += shift[k % 3];
          }
          xb = moved.data();
        }
      }
      adhesion::addCellContactForces(contact_, cells[a], cells[a].positionData(), forces_[a].data(), cells[b], xb,
                                     forces_[b].data());
    }
  }
}

std::array<double, 3> ExternalForces::nodeCentre(const mesh::SurfaceMesh& cell)
{
  std::array<double, 3> centre{};
  const double* x = cell.positionData();
  for (int k = 0; k < cell.numNodes(); ++k) {
    for (int i = 0; i < 3; ++i) {
      centre[static_cast<std::size_t>(i)] += x[3 * k + i] / cell.numNodes();
    }
  }
  return centre;
}

std::array<double, 3> ExternalForces::imageShift(const std::array<double, 3>& a, const std::array<double, 3>& b) const
{
  // a - (b + shift) = separation(a, b), the nearest images' separation.
  const std::array<double, 3> nearest = domain_.separation(a.data(), b.data());
  return {a[0] - b[0] - nearest[0], 0.0, a[2] - b[2] - nearest[2]};
}

std::vector<adhesion::ContactWall> contactWalls(const domain::Domain& domain)
{
  std::vector<adhesion::ContactWall> walls;
  for (const domain::Wall& wall : domain.walls()) {
    walls.push_back(adhesion::ContactWall{wall.height, wall.fluidSide});
  }
  return walls;
}

} // namespace capsula::scene
