#pragma once
// Checks of where the cells are: inside the domain (clear of its walls at the start, by a
// margin, and of their own periodic images), and not inside one another or their images. All are input errors (the deck's Center or size must change), raised before
// any work is done.
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <string>
#include <vector>

namespace capsula::scene {

/// Throws core::InputError naming `path` unless every node lies in the fluid: strictly on
/// the fluid side of every wall of `domain` (the lower wall y = 0, the upper wall y = H).
void requireInFluid(const mesh::SurfaceMesh& cell, const std::string& path, const domain::Domain& domain);

/// Throws core::InputError naming `path` unless every node lies farther than `minimumGap`
/// from every wall ('Wall/Minimum gap'): the check of the cells' starting places, which a run
/// may later leave (only crossing a wall stops it then).
void requireWallGaps(const mesh::SurfaceMesh& cell, const std::string& path, const domain::Domain& domain,
                     double minimumGap);

/// Throws core::InputError naming the key for a domain too small for the cell: a channel
/// not taller than the cell plus 'Wall/Minimum gap' on each side ('Wall/Channel height'),
/// a period not longer than the cell plus 'Cells/Minimum gap' (the cell would overlap its
/// own image; 'Domain/Periodic length x' or 'z').
void requireRoomInDomain(const mesh::SurfaceMesh& cell, const std::string& path, const domain::Domain& domain,
                         double minimumWallGap, double minimumCellGap);

/// Winding number of the closed surface about `point`: 1 inside, 0 outside (the surface
/// is taken as the four flat triangles of each 6-node element; for a point farther from
/// the surface than the chord height of an element the answer is exact).
double windingNumber(const mesh::SurfaceMesh& surface, const mesh::Vec3& point);

/// True if a node of either surface lies inside the other.
bool surfacesOverlap(const mesh::SurfaceMesh& a, const mesh::SurfaceMesh& b);

/// Throws core::InputError naming both cells if any two overlap, or touch: their surfaces
/// are no more than `minimumGap` apart (SurfaceGap.hpp; 'Cells/Minimum gap' of the deck,
/// the gap at which a run stops). Touching cells are rejected even with minimumGap = 0,
/// where a gap of exactly 0 remains. paths[i] names cell i. In a periodic `domain` each cell
/// is also checked against the images of the others in the neighbouring boxes.
void requireNoOverlap(const std::vector<const mesh::SurfaceMesh*>& cells, const std::vector<std::string>& paths,
                      double minimumGap = 0.0, const domain::Domain& domain = domain::Domain::unbounded());

} // namespace capsula::scene
