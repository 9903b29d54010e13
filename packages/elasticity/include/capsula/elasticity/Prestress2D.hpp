#pragma once
// Prestress of a 2D membrane (a contour), the 2D counterpart of Prestress.hpp: the cell
// starts inflated from its unstressed reference contour by the stretch 1 + alpha, so the
// reference is the initial contour shrunk by 1 + alpha about its area centroid, and the
// initial membrane carries the uniform tension E alpha (HookeanLaw2D). The thesis's 2D study
// (Chapter 4) has alpha = 0; a free cell in shear then starts with compressed arcs (the
// smallest tension is -0.147 E at tau = 0.7 for a/b = 1, Ca = 0.25), which a membrane
// without bending stiffness cannot resist: it wrinkles at the grid scale
// (docs/tether2d-results.md, "What stops the convergence").
#include <Eigen/Core>

namespace capsula::elasticity {

/// Reference nodes X = c + (x - c) / (1 + alpha) of the closed contour through `initial`
/// (c its area centroid). Throws InputError unless alpha is finite and >= 0 (0 gives
/// `initial` itself).
Eigen::Matrix2Xd prestressedReference2D(const Eigen::Matrix2Xd& initial, double prestress);

} // namespace capsula::elasticity
