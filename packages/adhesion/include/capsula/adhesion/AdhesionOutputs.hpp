#pragma once
// What a run records of one cell's adhesion at one step: the bonds, their total force on the
// membrane, the contact area and the smallest gap to the wall. Per-bond data for snapshots
// come from BondPopulation::records.
#include "capsula/adhesion/BondPopulation.hpp"
#include "capsula/adhesion/Receptors.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <Teuchos_Comm.hpp>

namespace capsula::adhesion {

struct AdhesionSummary {
  double bonds = 0.0;                        ///< number of bonds (mean field: expected)
  mesh::Vec3 bondForce = mesh::Vec3::Zero(); ///< total bond force on the membrane, G a
  double contactArea = 0.0;                  ///< membrane area within the reaction distance of the ligand wall, a^2
  double minimumGap = 0.0;                   ///< the smallest gap of a node to the ligand wall, a
};

/// The summary of cell `mesh` at node positions `positions` (3 per node). The contact area
/// is the sum of the nodes' area shares (ContactRepulsion.hpp) over the nodes within the
/// reaction distance: resolved to about one element's width.
AdhesionSummary summariseAdhesion(const BondPopulation& bonds, const mesh::SurfaceMesh& mesh,
                                  const ReceptorSet& receptors, const double* positions);

/// The receptors rank `rank` of `numRanks` updates: a contiguous block, the first
/// (numReceptors mod numRanks) blocks one longer.
struct ReceptorRange {
  int first = 0;
  int last = 0;
};
ReceptorRange ownedReceptors(int numReceptors, int rank, int numRanks);

/// After each rank has updated its ownedReceptors block, gives every rank the states of all
/// receptors (an exact sum of blocks padded with zeros). Collective over `comm`.
void shareBondStates(BondPopulation& bonds, const Teuchos::Comm<int>& comm);

} // namespace capsula::adhesion
