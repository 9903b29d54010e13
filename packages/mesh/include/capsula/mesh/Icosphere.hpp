#pragma once
// The unit-sphere mesh every 3D shape starts from (thesis Section 3.3, Table 3.1).
#include <capsula/mesh/SurfaceMesh.hpp>

namespace capsula::mesh {

/// Quadratic-triangle mesh of the unit sphere centred at the origin: the 20 faces
/// of an icosahedron are split into 4 children `level` times, new vertices being
/// projected radially onto the sphere at every level (this keeps the elements
/// closer to equilateral than projecting a flat 4^n subdivision once); the
/// midside nodes are the projected edge midpoints.
/// N_E = 20 * 4^level elements, N_P = 2 N_E + 2 nodes; vertex nodes are numbered
/// first (0 .. 10 * 4^level + 1), midside nodes after them. Outward orientation.
/// level must be in 0..7 (level 7 already has 327,680 elements).
SurfaceMesh makeIcosphere(int level);

} // namespace capsula::mesh
