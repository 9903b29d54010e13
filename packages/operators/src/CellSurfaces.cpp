#include "capsula/operators/CellSurfaces.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::operators {

namespace core = capsula::core;

CellSurfaces::CellSurfaces(std::vector<mesh::SurfaceMesh> cells, std::vector<double> viscosityRatios)
    : cells_(std::move(cells)), viscosityRatios_(std::move(viscosityRatios))
{
  core::require<core::InputError>(!cells_.empty(), "The boundary integrals need at least one cell.");
  core::require<core::InputError>(viscosityRatios_.size() == cells_.size(), "Got ", viscosityRatios_.size(),
                                  " viscosity ratios for ", cells_.size(), " cells; give one per cell.");
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    const double lambda = viscosityRatios_[c];
    core::require<core::InputError>(std::isfinite(lambda) && lambda > 0.0, "The viscosity ratio of cell ", c, " is ",
                                    lambda, "; it must be a finite number > 0.");
  }
  nodeOffsets_.assign(1, 0);
  elementOffsets_.assign(1, 0);
  for (const auto& cell : cells_) {
    nodeOffsets_.push_back(nodeOffsets_.back() + cell.numNodes());
    elementOffsets_.push_back(elementOffsets_.back() + cell.numElements());
  }
}

CellSurfaces::CellSurfaces(std::vector<mesh::SurfaceMesh> cells, double viscosityRatio)
    : CellSurfaces(cells, std::vector<double>(cells.size(), viscosityRatio))
{}

bool CellSurfaces::allViscosityRatiosOne() const
{
  return std::all_of(viscosityRatios_.begin(), viscosityRatios_.end(), [](double lambda) { return lambda == 1.0; });
}

int CellSurfaces::cellOfNode(int node) const
{
  const auto it = std::upper_bound(nodeOffsets_.begin(), nodeOffsets_.end(), node);
  return static_cast<int>(it - nodeOffsets_.begin()) - 1;
}

int CellSurfaces::cellOfElement(int element) const
{
  const auto it = std::upper_bound(elementOffsets_.begin(), elementOffsets_.end(), element);
  return static_cast<int>(it - elementOffsets_.begin()) - 1;
}

std::array<int, 6> CellSurfaces::elementNodes(int element) const
{
  const int c = cellOfElement(element);
  std::array<int, 6> nodes = cells_[c].element(element - elementOffsets_[c]);
  for (int& n : nodes) {
    n += nodeOffsets_[c];
  }
  return nodes;
}

void CellSurfaces::setPositions(const double* positions)
{
  for (int c = 0; c < numCells(); ++c) {
    cells_[c].setPositions(positions + 3 * nodeOffsets_[c]);
  }
}

std::vector<double> CellSurfaces::positions() const
{
  std::vector<double> all;
  all.reserve(3 * static_cast<std::size_t>(numNodes()));
  for (const auto& cell : cells_) {
    all.insert(all.end(), cell.positions().begin(), cell.positions().end());
  }
  return all;
}

} // namespace capsula::operators
