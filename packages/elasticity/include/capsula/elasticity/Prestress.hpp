#pragma once
// Membrane prestress (thesis Section 3.7, after Lac & Barthes-Biesel 2005): the cell
// starts inflated from its unstressed reference shape, alpha = a / a0 - 1 (eq 3.45),
// so the reference is the initial shape shrunk by 1 + alpha about its centroid. The initial
// membrane then carries a uniform isotropic tension that stabilises it against buckling.
//
// One map for the 3D surfaces and the 2D contours. A prestressed contour carries the uniform
// tension E alpha (HookeanLaw2D). The thesis's 2D study (Chapter 4) has alpha = 0; a free
// cell in shear then starts with compressed arcs (the smallest tension is -0.147 E at
// tau = 0.7 for a/b = 1, Ca = 0.25), which a membrane without bending stiffness cannot
// resist: it wrinkles at the grid scale (docs/tether2d-results.md, "What stops the
// convergence").
#include <capsula/mesh/SurfaceMesh.hpp>

#include <Eigen/Core>

#include <vector>

namespace capsula::elasticity {

/// Reference positions X = c + (x - c) / (1 + alpha) of the initial shape x (the mesh's
/// positions), c its volume centroid. Throws InputError unless alpha is finite and
/// >= 0 (0 gives the initial shape itself).
std::vector<double> prestressedReference(const mesh::SurfaceMesh& initialShape, double prestress);

/// The same for the nodes of the closed contour through `initial`, c its area centroid.
Eigen::Matrix2Xd prestressedReference(const Eigen::Matrix2Xd& initial, double prestress);

} // namespace capsula::elasticity
