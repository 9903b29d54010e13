#pragma once
// Random sequential placement of a suspension's cells in a periodic channel: the cells of
// each type, largest types first, each at a uniformly random orientation (a uniform random
// unit quaternion, Shoemake 1992) and a uniformly random centre of the box, accepted only if it
// keeps 'Wall/Minimum gap' from both walls, is shorter than the periods with
// 'Cells/Minimum gap' to spare (no overlap with its own images), and keeps 'Cells/Minimum gap'
// from every cell placed before and from their periodic images. Seeded and reproducible: the
// same seed, types and domain give the same cells on every machine (the random numbers come
// from std::mt19937_64, whose sequence the C++ standard fixes, turned into doubles here).
//
// Random sequential addition jams (near a volume fraction of 0.38 for spheres, lower for
// flat cells): a cell that finds no place in 'attempts' tries is an input error saying how far
// the packing got.
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <string>
#include <vector>

namespace capsula::suspension {

/// A cell type: its surface in the body frame (centred at the origin) and how many.
struct CellType {
  std::string name;
  mesh::SurfaceMesh shape;
  int count = 0;
};

struct PlacementSettings {
  unsigned long long seed = 1;
  double minimumCellGap = 0.05;  ///< 'Cells/Minimum gap'
  double minimumWallGap = 0.025; ///< 'Wall/Minimum gap'
  int attempts = 20000;          ///< tries per cell before the packing is declared jammed
};

/// One placed cell: its type (index into the types), the rigid motion from the body frame
/// (the deck's 'Center', 'Orientation axis', 'Orientation angle' in degrees) and its surface.
struct PlacedCell {
  int type = 0;
  mesh::Vec3 centre = mesh::Vec3::Zero();
  mesh::Vec3 axis = mesh::Vec3::UnitZ();
  double angleDegrees = 0.0;
  mesh::SurfaceMesh surface;
};

/// Places the cells of `types` in `domain`, a channel periodic along x and z. Throws
/// core::InputError naming the type and how many cells were placed when the packing jams,
/// and for a domain that is not a periodic channel.
std::vector<PlacedCell> placeCells(const std::vector<CellType>& types, const domain::Domain& domain,
                                   const PlacementSettings& settings);

/// The number of cells of volume `cellVolume` whose volume fraction in the channel of
/// `domain` is nearest to `hematocrit`. Throws core::InputError, naming
/// 'Suspension/Hematocrit', when that count misses the target by more than 1% of it (the
/// box is too small for the resolution of one cell) or is 0.
int cellsForHematocrit(double hematocrit, double cellVolume, const domain::Domain& domain);

} // namespace capsula::suspension
