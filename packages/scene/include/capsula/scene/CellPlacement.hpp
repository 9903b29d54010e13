#pragma once
// Checks of where the cells are: above the wall (at the start, by a margin), and not inside
// one another. All are input errors (the deck's Center or size must change), raised before
// any work is done.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <string>
#include <vector>

namespace capsula::scene {

/// Throws core::InputError naming `path` unless every node lies in the fluid, y > 0 (the
/// wall is the plane y = 0).
void requireAboveWall(const mesh::SurfaceMesh& cell, const std::string& path);

/// Throws core::InputError naming `path` unless every node lies higher than `minimumGap`
/// above the wall ('Wall/Minimum gap'): the check of the cells' starting places, which a run
/// may later leave (only crossing the wall stops it then).
void requireWallGap(const mesh::SurfaceMesh& cell, const std::string& path, double minimumGap);

/// Winding number of the closed surface about `point`: 1 inside, 0 outside (the surface
/// is taken as the four flat triangles of each 6-node element; for a point farther from
/// the surface than the chord height of an element the answer is exact).
double windingNumber(const mesh::SurfaceMesh& surface, const mesh::Vec3& point);

/// True if a node of either surface lies inside the other.
bool surfacesOverlap(const mesh::SurfaceMesh& a, const mesh::SurfaceMesh& b);

/// Throws core::InputError naming both cells if any two overlap, or touch: their surfaces
/// are no more than `minimumGap` apart (SurfaceGap.hpp; 'Cells/Minimum gap' of the deck,
/// the gap at which a run stops). Touching cells are rejected even with minimumGap = 0,
/// where a gap of exactly 0 remains. paths[i] names cell i.
void requireNoOverlap(const std::vector<const mesh::SurfaceMesh*>& cells, const std::vector<std::string>& paths,
                      double minimumGap = 0.0);

} // namespace capsula::scene
