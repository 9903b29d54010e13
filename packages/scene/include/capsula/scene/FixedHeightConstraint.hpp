#pragma once
// Fixed cell height (thesis Section 5.1): the height of a cell's centroid above the wall
// is held constant by removing the cell's mean vertical velocity from all its nodes, at
// every Runge-Kutta stage (a timeint::StageConstraint).
//
// "Mean" is the volume-weighted one, the rate of change of the centroid,
// w = dy_c/dt = (1/V) int_S (y - y_c)(u . n) dS (CellKinematics.hpp). A uniform vertical
// velocity w moves the centroid by exactly w, so after the subtraction dy_c/dt = 0 at
// every stage and the height stays fixed to the accuracy of the time integration. The
// plain average over nodes would not: nodes crowd where the mesh is fine, so a
// tank-treading cell would drift.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::scene {

class FixedHeightConstraint {
public:
  /// `cells` are the constrained cells (their topology; positions are taken from the
  /// state), `nodeOffsets[k]` the index of cell k's first node in the global state.
  FixedHeightConstraint(std::vector<mesh::SurfaceMesh> cells, std::vector<int> nodeOffsets);

  int numCells() const { return static_cast<int>(cells_.size()); }

  /// Removes each constrained cell's centroid rise rate from the vertical velocity of its
  /// nodes in `velocities`; `positions` is the state the velocities belong to.
  void apply(const std::vector<double>& positions, std::vector<double>& velocities);

private:
  std::vector<mesh::SurfaceMesh> cells_;
  std::vector<int> nodeOffsets_;
};

} // namespace capsula::scene
