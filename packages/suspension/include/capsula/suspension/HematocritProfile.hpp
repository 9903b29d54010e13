#pragma once
// The hematocrit (volume fraction of cells) across a periodic channel: the channel 0 < y < H
// cut into slabs of equal thickness, and in each the volume of the cells it holds over the
// slab's volume L_x dy L_z (SlabVolumes.hpp, exact for the flat-faceted surfaces). Positions
// need no folding: a slab extends over the whole box along x and z.
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::suspension {

struct HematocritProfile {
  std::vector<double> heights;  ///< the slab boundaries 0 = y_0 < ... < y_n = H
  std::vector<double> fraction; ///< the cells' volume fraction in each slab
  double mean = 0.0;            ///< the cells' volume over the channel's, L_x H L_z
};

/// The profile of `cells` in `numSlabs` slabs. Throws core::InputError unless `domain` is a
/// channel periodic along x and z (the box's volume is finite) and numSlabs >= 1.
HematocritProfile hematocritProfile(const std::vector<const mesh::SurfaceMesh*>& cells, const domain::Domain& domain,
                                    int numSlabs);

/// The profile of `cells` in `numSlabs` slabs across 0 < y < `top`, each slab's volume
/// fraction taken over `area` dy (area: the box's extent along x times along z), whatever
/// the cells' x and z. The parts of cells outside 0 < y < top are not counted. The profile of
/// a periodic channel is this with top = H and area = L_x L_z. Throws core::InputError
/// unless top > 0, area > 0 and numSlabs >= 1.
HematocritProfile hematocritProfileInSlab(const std::vector<const mesh::SurfaceMesh*>& cells, double top, double area,
                                          int numSlabs);

} // namespace capsula::suspension
