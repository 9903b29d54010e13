#pragma once
// The receptor-ligand bonds of a scene's cells (packages/adhesion): per cell its receptors,
// material points placed on the cell's reference shape from 'Adhesion/Seed', and their
// bonds to the ligands of the wall y = 0.
//
// The bond set is frozen while a time step's stages are evaluated: the velocity is a
// function of the positions and of the bonds as they are, so the integrator's error
// control sees a smooth right-hand side. Only update() changes the set, after an accepted
// step (run/RunScene.hpp), by Monte Carlo or the mean field over that step.
//
// Every rank holds every state. update() has each rank advance its ownedReceptors block of
// every cell and shareBondStates gather the blocks; the draws are counter-based (seed, cell,
// receptor, step), so the states are those of any other partition, bit for bit.
#include <capsula/adhesion/AdhesionOutputs.hpp>
#include <capsula/adhesion/AdhesionParameters.hpp>
#include <capsula/adhesion/BondPopulation.hpp>
#include <capsula/adhesion/Receptors.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <Teuchos_Comm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace capsula::scene {

class SceneBonds {
public:
  /// Places the receptors of each cell of `cells` on its unstressed shape `references[c]`
  /// (3 per node), all free. The cell index is the random stream that tells cells apart.
  SceneBonds(const adhesion::AdhesionSettings& settings, const std::vector<mesh::SurfaceMesh>& cells,
             const std::vector<std::vector<double>>& references);

  const adhesion::AdhesionSettings& settings() const { return settings_; }
  int numCells() const { return static_cast<int>(receptors_.size()); }
  const adhesion::ReceptorSet& receptors(int c) const { return receptors_[static_cast<std::size_t>(c)]; }
  const adhesion::BondPopulation& bonds(int c) const { return bonds_[static_cast<std::size_t>(c)]; }
  /// For a test that sets bonds by hand (BondPopulation::setState).
  adhesion::BondPopulation& bonds(int c) { return bonds_[static_cast<std::size_t>(c)]; }
  /// All cells' bonds (the number; its expectation in the mean field).
  double bondCount() const;

  /// Adds the bond forces on cell `c` (`cell` its mesh, `positions` 3 per node) to
  /// `nodalForces` (3 per node) as virtual-work nodal forces (adhesion/PointForces.hpp);
  /// returns their total.
  mesh::Vec3 addNodalForces(int c, const mesh::SurfaceMesh& cell, const double* positions, double* nodalForces) const;

  /// Formation and breakage of cell c's bonds over the accepted step numbered `step` of
  /// length `dt`, the receptors where `positions` puts them. Collective over `comm`.
  adhesion::BondEvents update(int c, const mesh::SurfaceMesh& cell, const double* positions, double dt,
                              std::uint64_t step, const Teuchos::Comm<int>& comm);

  /// Bonds, their total force, the contact area and the gap of cell c (AdhesionOutputs.hpp).
  adhesion::AdhesionSummary summary(int c, const mesh::SurfaceMesh& cell, const double* positions) const;

  /// Cell c's bond states for a checkpoint: occupancy and anchor (x, y, z), 4 per receptor.
  std::vector<double> states(int c) const;
  /// Restores them. Throws core::InputError naming `source` if they do not fit the receptors.
  void restoreStates(int c, const std::vector<double>& states, const std::string& source);

  /// The term line of the run log: the model, the rates and the receptors per cell.
  std::string describe() const;

private:
  adhesion::AdhesionSettings settings_;
  std::vector<adhesion::ReceptorSet> receptors_;
  std::vector<adhesion::BondPopulation> bonds_;
};

} // namespace capsula::scene
