#pragma once
// The smallest distance between the surfaces of two cells: how close two capsules come
// (thesis Chapter 6), for the pair metrics and for the safety stop of a run whose cells
// are about to touch.
//
// Each surface is taken as its nodes and the four flat triangles of each 6-node element
// (the same pieces as windingNumber). The gap is the smallest distance from a node of one
// surface to a flat triangle of the other, both ways round. The nodes lie on the curved
// surface, the flat triangles inside it by at most the chord sag of an element,
// ~ kappa h^2 / 8 (h the length of a flat piece: ~0.3 a at level 2, sag ~0.01 a), so the
// gap of the discrete surfaces is exact for flat facets and overestimates the gap of the
// curved ones by at most one sag. It is not a signed distance: surfaces that cross give a
// small positive number (surfacesOverlap in CellPlacement.hpp detects overlap).
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

namespace capsula::scene {

/// The closest point of the triangle (a, b, c) to p (a degenerate triangle is handled as
/// its edges).
mesh::Vec3 closestPointOnTriangle(const mesh::Vec3& p, const mesh::Vec3& a, const mesh::Vec3& b, const mesh::Vec3& c);

struct SurfaceGap {
  double distance = 0.0;                    ///< >= 0
  mesh::Vec3 onFirst = mesh::Vec3::Zero();  ///< the closest points: on the first surface
  mesh::Vec3 onSecond = mesh::Vec3::Zero(); ///< and on the second
};

/// The gap between surface `a` at positions `xa` and surface `b` at `xb` (3 doubles per
/// node, each mesh's numbering). Cost O(N_a T_b + N_b T_a) in the worst case; nodes
/// farther from the other surface's bounding box than the best gap so far are skipped,
/// so cells a few radii apart cost little more than the two bounding boxes.
SurfaceGap minimumSurfaceGap(const mesh::SurfaceMesh& a, const double* xa, const mesh::SurfaceMesh& b,
                             const double* xb);

/// The same at the meshes' own positions.
SurfaceGap minimumSurfaceGap(const mesh::SurfaceMesh& a, const mesh::SurfaceMesh& b);

/// The gap between surface `a` and the nearest periodic image of surface `b` in `domain`:
/// the smallest over b shifted by 0 and +-1 period along each periodic axis, which holds the
/// nearest image of every point of a cell shorter than a period (CellPlacement.hpp's
/// requireRoomInDomain). onSecond is given on b itself, not on its image. Without periodic
/// directions, minimumSurfaceGap(a, xa, b, xb).
SurfaceGap minimumSurfaceGap(const mesh::SurfaceMesh& a, const double* xa, const mesh::SurfaceMesh& b, const double* xb,
                             const domain::Domain& domain);

} // namespace capsula::scene
