#pragma once
// The bonds of one cell's receptors to the ligands of the ligand wall (AdhesionSettings::
// ligandWall: the wall y = 0, or a channel's upper wall), advanced one time step at a time by
// Monte Carlo (Hammer & Apte 1992) or by their mean field. "Below" a receptor means the
// point of that wall nearest to it, its gap the distance to it.
//
// Each receptor carries a state: its occupancy (stochastic: 0 free or 1 bonded; mean field:
// the probability p of being bonded) and the anchor, the ligand position on the wall where
// its bond formed (directly below the receptor at formation, Hammer & Apte 1992). A bond of
// length L = |x - anchor| pulls the membrane at the receptor with
//   F = -sigma (L - lambda) (x - anchor) / L     (times p in the mean field),
// towards the anchor when stretched, away when compressed.
//
// Stochastic step, with the rates of BondKinetics.hpp at the receptor's position after the
// step, frozen over it: the exact two-state chain free <-> bound over dt, a receptor binding
// and breaking as often as the rates make it. A bond breaks if u_b < 1 - exp(-k_off dt), at
// s = -ln(1 - u_b) / k_off; a receptor free at the start (or from s on) is bound at the end
// if u_f < k_on / (k_on + k_off') (1 - exp(-(k_on + k_off') t)), t = dt (or dt - s), k_off'
// the rate of a fresh bond to the point below it, where that bond is anchored. For rates
// constant over the step this is the law of the continuous-time process for every k dt: the
// bound fraction of a clamped population settles at k_on / (k_on + k_off) whatever the step
// (one event per receptor per step, the Monte Carlo of Hammer & Apte 1992, settles at
// p_on / (p_on + p_off), p = 1 - exp(-k dt), instead: 0.578 for k_on = 2, k_off = 1, dt = 1,
// against 2/3). u_f, u_b are counter-based draws of (seed, stream, receptor, step)
// (CounterRandom.hpp), so the events do not depend on which rank holds a receptor or on the
// order receptors are visited: update() takes a range of receptors, and ranges updated in any
// order or on any rank give the same states.
//
// Mean-field step: p <- p_eq + (p - p_eq) exp(-(k_on + k_off) dt), p_eq = k_on / (k_on +
// k_off), the exact solution of the master equation dp/dt = k_on (1 - p) - k_off p with the
// rates frozen over the step. The anchor is the occupancy-weighted mean of the surviving
// bonds' anchor (weight p exp(-k_off dt)) and the new bonds' (the point below the receptor).
#include "capsula/adhesion/AdhesionParameters.hpp"
#include "capsula/adhesion/LoadStiffness.hpp"
#include "capsula/adhesion/Receptors.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <cstdint>
#include <vector>

namespace capsula::adhesion {

struct BondState {
  double occupancy = 0.0; ///< stochastic: 0 or 1; mean field: probability in [0, 1]
  mesh::Vec3 anchor = mesh::Vec3::Zero();
};

/// What one update did to the receptors it visited (stochastic events; 0 in the mean field).
struct BondEvents {
  int formed = 0;
  int broken = 0;
};

/// One bond, for snapshots.
struct BondRecord {
  int receptor = 0;
  double occupancy = 0.0;
  mesh::Vec3 position = mesh::Vec3::Zero(); ///< the receptor
  mesh::Vec3 anchor = mesh::Vec3::Zero();   ///< the ligand on the wall
  mesh::Vec3 force = mesh::Vec3::Zero();    ///< on the membrane, occupancy included
};

class BondPopulation {
public:
  /// All `numReceptors` receptors free. `stream` tells the cells apart (the cell index, as
  /// for its ReceptorSet).
  BondPopulation(const AdhesionSettings& settings, std::uint64_t stream, int numReceptors);

  const AdhesionSettings& settings() const { return settings_; }
  int size() const { return static_cast<int>(states_.size()); }
  const BondState& state(int r) const { return states_[static_cast<std::size_t>(r)]; }
  const std::vector<BondState>& states() const { return states_; }
  /// Sets a receptor's state (a restart, a test). Throws core::InputError for an occupancy
  /// outside [0, 1] (stochastic: other than 0 or 1).
  void setState(int r, const BondState& state);

  /// Advances receptors first..last-1 over a step of length dt, the step numbered `step`
  /// (the same number on every rank), their positions from the node positions
  /// `positions` (3 per node of `mesh`).
  BondEvents update(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors, const double* positions, double dt,
                    std::uint64_t step, int first, int last);
  /// The same for all receptors.
  BondEvents update(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors, const double* positions, double dt,
                    std::uint64_t step)
  {
    return update(mesh, receptors, positions, dt, step, 0, size());
  }

  /// Sum of the occupancies: the number of bonds (mean field: its expectation).
  double bondCount() const;
  /// The force of receptor r's bond on the membrane when the receptor is at `x`.
  mesh::Vec3 force(int r, const mesh::Vec3& x) const;

  /// Adds the bonds' nodal forces c_k F of receptors first..last-1 (c_k the receptor's node
  /// shares, Receptors.hpp: phi_k at a point, as PointForces.hpp) to `nodalForces` (3 per
  /// node of `mesh`); returns their total.
  mesh::Vec3 addNodalForces(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors, const double* positions,
                            double* nodalForces, int first, int last) const;
  mesh::Vec3 addNodalForces(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors, const double* positions,
                            double* nodalForces) const
  {
    return addNodalForces(mesh, receptors, positions, nodalForces, 0, size());
  }

  /// Adds the stiffness -dF_k/dx_l of the bonds' nodal forces F_k = c_k F(x), x = sum_l
  /// c_l x_l, to `stiffness`: c_k c_l occupancy sigma [(1 - lambda/L) I + (lambda/L) e e^T]
  /// per bond of length L along e, the Hessian of its energy sigma (L - lambda)^2 / 2.
  void addStiffness(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors, const double* positions,
                    LoadStiffness& stiffness) const;

  /// The bonds with occupancy > 0, in receptor order.
  std::vector<BondRecord> records(const mesh::SurfaceMesh& mesh, const ReceptorSet& receptors,
                                  const double* positions) const;

private:
  void stochasticStep(BondState& state, const mesh::Vec3& x, double dt, std::uint64_t receptor, std::uint64_t step,
                      BondEvents& events) const;
  void meanFieldStep(BondState& state, const mesh::Vec3& x, double dt) const;

  AdhesionSettings settings_;
  std::uint64_t stream_;
  std::vector<BondState> states_;
};

} // namespace capsula::adhesion
