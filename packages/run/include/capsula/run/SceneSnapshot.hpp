#pragma once
// What a snapshot of a scene holds (io::Snapshot, XDMF Triangle_6 for ParaView): one
// block per cell, "cell0", "cell1", ..., with
//   node fields  velocity (3), tension_major, tension_minor (eq 3.30), stretch_major,
//                stretch_minor
//   cell fields  load <Delta f>_m (3), shear_stress |<Delta f>_m| (eq 3.57)
// and, when the wall shear stress is computed, a block "wall" (2DSMesh, on y = 0) with the
// fields shear_stress (eq 3.63), dudy and dwdy, and in a channel a block "upper_wall"
// (2DSMesh, on y = H) with shear_stress, dudn and dwdn, n = -e_y its normal into the fluid
// (WallShearStressMap.hpp: the fluid's traction on that wall); with adhesion, for every cell with bonds a block
// "bonds0", "bonds1", ... (Polyline, two nodes per bond: the receptor and its ligand on the
// wall) with the cell fields force (on the membrane, 3), occupancy and receptor (its index).
// The block, and so the mesh version, changes with the number of bonds. With a tether, a
// block "tether" (Polyline, one segment from the attachment point to the anchor) with the
// cell fields force (on the membrane, 3) and length.
// Positions are the run's own, unfolded (a cell that left a periodic box is drawn where it
// travelled), unless `foldIntoBox`: then each cell, with its bonds and tether, is drawn moved
// by the lattice vector that brings the mean of its nodes into the box [0, L_x) x R x
// [0, L_z) (domain::Domain::foldingShift), whole, so that a suspension stays in view.
#include <capsula/io/Snapshot.hpp>
#include <capsula/operators/WallShearStress.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/run/WallShearStressMap.hpp>

#include <cstdint>

namespace capsula::run {

io::Snapshot sceneSnapshot(const scene::Scene& scene, const scene::SceneFields& fields, double time, std::int64_t step,
                           bool foldIntoBox = false);

io::SnapshotBlock wallSnapshotBlock(const WallGrid& grid, const operators::WallShearStress& stress);

} // namespace capsula::run
