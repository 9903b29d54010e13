#pragma once
// Membrane prestress (thesis Section 3.7, after Lac & Barthes-Biesel 2005): the cell
// starts inflated from its unstressed reference shape, alpha = a / a0 - 1 (eq 3.45),
// so the reference is the initial shape shrunk by 1 + alpha. The initial membrane
// then carries a uniform isotropic tension that stabilises it against buckling.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::elasticity {

/// Reference positions X = c + (x - c) / (1 + alpha) of the initial shape x (the mesh's
/// positions), c its volume centroid. Throws InputError unless alpha is finite and
/// >= 0 (0 gives the initial shape itself).
std::vector<double> prestressedReference(const mesh::SurfaceMesh& initialShape, double prestress);

} // namespace capsula::elasticity
