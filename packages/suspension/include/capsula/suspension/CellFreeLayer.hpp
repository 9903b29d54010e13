#pragma once
// The cell-free layer along each wall of a periodic channel, defined as in the margination
// literature's 2D and 3D studies (the distance from the wall to the outer edge of the
// red-cell core), here per column: a regular grid of columns (x, z) covers the box; along
// each, the distance from the wall to the first red-cell surface it meets, capped at H/2 (a
// column that meets no cell before the centre-plane counts H/2); the layer is the mean over
// the columns. Exact for the flat-faceted surfaces (FlatFacets.hpp) up to the column
// sampling. Cells may lie anywhere (positions are not folded): each is brought into the box
// by the shift of its first node, and its images in the neighbouring boxes are seen too.
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::suspension {

struct CellFreeLayer {
  double lower = 0.0; ///< mean distance from the wall y = 0 to the first cell surface
  double upper = 0.0; ///< the same from the wall y = H
};

/// The layer of `cells` sampled on columnsX x columnsZ columns at the centres of a regular
/// grid. Throws core::InputError unless `domain` is a channel periodic along x and z and
/// both counts are >= 1.
CellFreeLayer cellFreeLayer(const std::vector<const mesh::SurfaceMesh*>& cells, const domain::Domain& domain,
                            int columnsX, int columnsZ);

/// The thinnest cell-free layer, for a domain without a periodic box to lay columns over: the
/// smallest distance from the lower wall to a cell surface (`lower`) and, in a channel, from
/// the upper wall (`upper`, else +infinity). The fine-column limit of the smallest column's
/// layer above, uncapped; exact for the flat-faceted surfaces, whose extreme heights lie at
/// their corners, the mesh nodes. Throws core::InputError without the lower wall or cells.
CellFreeLayer thinnestCellFreeLayer(const std::vector<const mesh::SurfaceMesh*>& cells, const domain::Domain& domain);

} // namespace capsula::suspension
