#pragma once
// Volume conservation of a cell ('Cells/Cell k/Conserve volume'): the net normal flux of the
// cell's node velocities through its surface is removed at every Runge-Kutta stage (a
// timeint::StageConstraint, as FixedHeightConstraint).
//
// An incompressible interior makes int_S u . n dS = 0 exact; the discrete single layer does
// not, and near a wall its error is large. Measured on a Ca = 3e-4 Skalak cell (C = 2.5,
// ROS34PW2, level 1, to t = 1): 0.03 a above the wall it loses 0.45% of its volume, at 2 a
// above it or without a wall 1e-5 to 8e-5; at level 2, 0.03 a above the wall, it gains 1.8%
// by t = 5, the gain growing 2.5-fold per unit time (docs/cell3d-adhesion-results.md).
// The constraint subtracts c n_k from every node velocity u_k, n_k the area-averaged node
// normal, with
//
//   c = int_S (sum_k phi_k u_k) . n dS / int_S (sum_k phi_k n_k) . n dS,
//
// so that the interpolated velocity carries no net flux (N_Q-point rule, current shape).
// The rate of change of the enclosed volume of the quadratic surface is that flux up to the
// motion of the elements' shape parameters, so the volume is held to the accuracy of the
// time integration and of that term. A rigid motion or a flux-free shape change passes
// unchanged to the rule's accuracy.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::scene {

/// int_S (sum_k phi_k v_k) . n dS over `cell` in its current positions, `values` 3 per node:
/// the net normal flux of an interpolated nodal field.
double normalFlux(const mesh::SurfaceMesh& cell, const double* values, int numQuadraturePoints = 12);

class VolumeConstraint {
public:
  /// `cells` are the constrained cells (their topology; positions are taken from the
  /// state), `nodeOffsets[k]` the index of cell k's first node in the global state.
  VolumeConstraint(std::vector<mesh::SurfaceMesh> cells, std::vector<int> nodeOffsets);

  int numCells() const { return static_cast<int>(cells_.size()); }

  /// Removes each constrained cell's net normal flux from its node velocities in
  /// `velocities` (see above); `positions` is the state the velocities belong to.
  void apply(const std::vector<double>& positions, std::vector<double>& velocities);

private:
  std::vector<mesh::SurfaceMesh> cells_;
  std::vector<int> nodeOffsets_;
  std::vector<double> normals_; // 3 per node of the cell being constrained
};

} // namespace capsula::scene
