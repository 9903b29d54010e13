#pragma once
// The bounds the cells set on the receptors of 'Adhesion': how many fit, and how wide a
// receptor's patch may be before its pulling point leaves the reach of the wall.
#include <capsula/adhesion/AdhesionParameters.hpp>
#include <capsula/adhesion/Receptors.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <cstddef>
#include <vector>

namespace capsula::scene {

/// What one receptor costs: its material point (24 bytes), its bond state (32), the copy of
/// the state gathered from the ranks (32) and its row in the outputs (32), rounded up.
constexpr std::size_t kBytesPerReceptor = 128;

/// The most receptors a process can hold: its machine's physical memory over
/// kBytesPerReceptor, and no more than a receptor index (int) counts.
double receptorCapacity();

/// Refuses an 'Adhesion/Receptor density' that puts more than receptorCapacity() receptors
/// on the cells' reference shapes, naming the count and the largest density that fits.
void requireReceptorsFit(const adhesion::AdhesionSettings& settings, const std::vector<mesh::SurfaceMesh>& cells,
                         const std::vector<std::vector<double>>& references);

/// Refuses an 'Adhesion/Patch radius' whose patches put a receptor's pulling point (the
/// weighted mean of its patch, on the unstressed shape) deeper inside the membrane than
/// r_0 - lambda ('Reaction distance' - 'Equilibrium length'): on a membrane held at the bonds'
/// rest length such a receptor is out of reach, and binds only if the membrane flattens over
/// the patch's whole width (0 bonds where point receptors make 30). A necessary condition: a
/// patch within it may still bind late. `receptors` holds its patches already; names the
/// depth and the widest radius that keeps it within r_0 - lambda.
void requirePatchesWithinReach(const adhesion::AdhesionSettings& settings, const adhesion::ReceptorSet& receptors,
                               const mesh::SurfaceMesh& cell, const std::vector<double>& reference);

} // namespace capsula::scene
