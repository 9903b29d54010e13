#pragma once
// The surfaces the boundary integrals run over: every cell of a scene, each a closed
// SurfaceMesh with its own viscosity ratio lambda = mu_inside / mu_outside.
//
// Nodes and elements of all cells share one global numbering, cell after cell: cell c
// holds nodes [nodeOffset(c), nodeOffset(c + 1)) and elements likewise. Every flat array
// the operators exchange uses it: positions and velocities (3 per node), element loads
// (3 per element).
#include <capsula/mesh/SurfaceMesh.hpp>

#include <array>
#include <vector>

namespace capsula::operators {

class CellSurfaces {
public:
  /// Throws core::InputError unless there is at least one cell and one finite viscosity
  /// ratio > 0 per cell.
  CellSurfaces(std::vector<mesh::SurfaceMesh> cells, std::vector<double> viscosityRatios);

  /// One viscosity ratio for every cell.
  CellSurfaces(std::vector<mesh::SurfaceMesh> cells, double viscosityRatio);

  int numCells() const { return static_cast<int>(cells_.size()); }
  const mesh::SurfaceMesh& cell(int c) const { return cells_[c]; }
  double viscosityRatio(int c) const { return viscosityRatios_[c]; }
  bool allViscosityRatiosOne() const;

  int numNodes() const { return nodeOffsets_.back(); }
  int numElements() const { return elementOffsets_.back(); }
  int nodeOffset(int c) const { return nodeOffsets_[c]; }
  int elementOffset(int c) const { return elementOffsets_[c]; }
  int cellOfNode(int node) const;
  int cellOfElement(int element) const;

  /// Global node numbers of the six nodes of global element `element`.
  std::array<int, 6> elementNodes(int element) const;

  /// Replaces the positions of all cells from one flat array (3 * numNodes()).
  void setPositions(const double* positions);
  /// All positions, flat, in the global numbering.
  std::vector<double> positions() const;

private:
  std::vector<mesh::SurfaceMesh> cells_;
  std::vector<double> viscosityRatios_;
  std::vector<int> nodeOffsets_;
  std::vector<int> elementOffsets_;
};

} // namespace capsula::operators
