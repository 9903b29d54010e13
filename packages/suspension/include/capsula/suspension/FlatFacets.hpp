#pragma once
// The flat-faceted surface of a 6-node cell mesh: each curved element as the four flat
// triangles of its corner and midside nodes, oriented like the element (outward normal).
// The suspension measures (volumes in slabs, the cell-free layer) are exact for this
// polyhedron, whose volume differs from the curved surface's by O(h^2).
#include <capsula/mesh/SurfaceMesh.hpp>

#include <array>
#include <functional>

namespace capsula::suspension {

/// The local node numbers of the four flat triangles of an element (mesh/SurfaceMesh.hpp:
/// corners 0-2, midside nodes 3 (edge 0-1), 4 (1-2), 5 (2-0)).
inline constexpr std::array<std::array<int, 3>, 4> flatFacetPieces{{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}};

/// Calls `visit(p0, p1, p2)` for every flat triangle of `surface` at `positions` (3
/// doubles per node), shifted by `shift`.
void forEachFlatFacet(const mesh::SurfaceMesh& surface, const double* positions, const mesh::Vec3& shift,
                      const std::function<void(const mesh::Vec3&, const mesh::Vec3&, const mesh::Vec3&)>& visit);

} // namespace capsula::suspension
