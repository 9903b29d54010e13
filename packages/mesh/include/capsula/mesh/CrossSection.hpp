#pragma once
// The curve where a plane cuts the surface: cell profiles for figures (e.g. the
// plane z = z_c through the centroid).
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <vector>

namespace capsula::mesh {

struct Polyline {
  std::vector<Vec3> points;
  bool closed = false; ///< the last point joins the first
};

/// Cuts the mesh with the plane through `planePoint` with normal `planeNormal`. Each
/// element is split into subdivisions^2 parametric sub-triangles whose vertices lie on
/// the quadratic surface; the cut is linear within a sub-triangle, so points lie within
/// O((h / subdivisions)^2) of the surface curve. Returns one polyline per connected
/// piece of the cut (closed loops for a closed surface), each loop ordered
/// counter-clockwise seen from the side planeNormal points to. Empty if the plane
/// misses the surface.
std::vector<Polyline> crossSection(const SurfaceMesh& mesh, const Vec3& planePoint, const Vec3& planeNormal,
                                   int subdivisions = 8);

} // namespace capsula::mesh
