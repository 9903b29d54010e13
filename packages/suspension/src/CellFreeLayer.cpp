#include "capsula/suspension/CellFreeLayer.hpp"

#include "capsula/suspension/FlatFacets.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace capsula::suspension {

namespace {

using mesh::Vec3;

// The lowest and highest height at which the columns meet a cell surface (infinities: none).
struct ColumnHits {
  int columnsX = 0, columnsZ = 0;
  double spacingX = 0.0, spacingZ = 0.0;
  std::vector<double> lowest, highest;

  ColumnHits(int nx, int nz, double lx, double lz)
      : columnsX(nx),
        columnsZ(nz),
        spacingX(lx / nx),
        spacingZ(lz / nz),
        lowest(static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz), std::numeric_limits<double>::infinity()),
        highest(lowest.size(), -std::numeric_limits<double>::infinity())
  {}

  // Records the heights at which the flat triangle (p0, p1, p2) crosses the columns whose
  // centres its (x, z) projection covers (barycentric coordinates in the projection).
  void addTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2)
  {
    const double ax = p1[0] - p0[0], az = p1[2] - p0[2];
    const double bx = p2[0] - p0[0], bz = p2[2] - p0[2];
    const double det = ax * bz - az * bx;
    if (det == 0.0) { // parallel to the columns: met only along an edge, which a neighbour holds
      return;
    }
    const double xMin = std::min({p0[0], p1[0], p2[0]}), xMax = std::max({p0[0], p1[0], p2[0]});
    const double zMin = std::min({p0[2], p1[2], p2[2]}), zMax = std::max({p0[2], p1[2], p2[2]});
    // Columns i with centre (i + 1/2) spacing in [min, max], clipped to the box.
    const int iFirst = std::max(0, static_cast<int>(std::ceil(xMin / spacingX - 0.5)));
    const int iLast = std::min(columnsX - 1, static_cast<int>(std::floor(xMax / spacingX - 0.5)));
    const int kFirst = std::max(0, static_cast<int>(std::ceil(zMin / spacingZ - 0.5)));
    const int kLast = std::min(columnsZ - 1, static_cast<int>(std::floor(zMax / spacingZ - 0.5)));
    for (int i = iFirst; i <= iLast; ++i) {
      for (int k = kFirst; k <= kLast; ++k) {
        const double px = (i + 0.5) * spacingX - p0[0], pz = (k + 0.5) * spacingZ - p0[2];
        const double s = (px * bz - pz * bx) / det, t = (ax * pz - az * px) / det;
        if (s < 0.0 || t < 0.0 || s + t > 1.0) {
          continue;
        }
        const double y = p0[1] + s * (p1[1] - p0[1]) + t * (p2[1] - p0[1]);
        const std::size_t column =
            static_cast<std::size_t>(i) * static_cast<std::size_t>(columnsZ) + static_cast<std::size_t>(k);
        lowest[column] = std::min(lowest[column], y);
        highest[column] = std::max(highest[column], y);
      }
    }
  }
};

} // namespace

CellFreeLayer cellFreeLayer(const std::vector<const mesh::SurfaceMesh*>& cells, const domain::Domain& domain,
                            int columnsX, int columnsZ)
{
  core::require<core::InputError>(domain.hasUpperWall() && domain.isPeriodic(domain::flowAxis) &&
                                      domain.isPeriodic(domain::vorticityAxis),
                                  "The cell-free layer is measured in a channel periodic along x and z ('Wall/Channel "
                                  "height', 'Domain/Periodic length x' and 'z' all > 0), not in ",
                                  domain.describe(), ".");
  core::require<core::InputError>(columnsX >= 1 && columnsZ >= 1, "The cell-free layer needs at least one column, not ",
                                  columnsX, " x ", columnsZ, ".");
  const double lx = domain.period(domain::flowAxis), lz = domain.period(domain::vorticityAxis);
  ColumnHits hits(columnsX, columnsZ, lx, lz);
  for (const mesh::SurfaceMesh* cell : cells) {
    // The shift that brings the cell's first node into the box, then the neighbouring images:
    // a cell shorter than a period (CellPlacement.hpp) covers columns of at most these.
    const auto folding = domain.foldingShift(cell->positionData());
    for (int i = -1; i <= 1; ++i) {
      for (int k = -1; k <= 1; ++k) {
        const Vec3 shift(folding[0] + i * lx, 0.0, folding[2] + k * lz);
        forEachFlatFacet(*cell, cell->positionData(), shift,
                         [&](const Vec3& p0, const Vec3& p1, const Vec3& p2) { hits.addTriangle(p0, p1, p2); });
      }
    }
  }
  const double height = domain.channelHeight();
  const double cap = 0.5 * height;
  CellFreeLayer layer;
  for (std::size_t c = 0; c < hits.lowest.size(); ++c) {
    layer.lower += std::min(hits.lowest[c], cap);
    layer.upper += std::min(height - hits.highest[c], cap);
  }
  layer.lower /= static_cast<double>(hits.lowest.size());
  layer.upper /= static_cast<double>(hits.lowest.size());
  return layer;
}

CellFreeLayer thinnestCellFreeLayer(const std::vector<const mesh::SurfaceMesh*>& cells, const domain::Domain& domain)
{
  core::require<core::InputError>(domain.hasLowerWall() && !cells.empty(),
                                  "The thinnest cell-free layer needs the lower wall and cells, not ",
                                  domain.describe(), " with ", cells.size(), " cells.");
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -std::numeric_limits<double>::infinity();
  for (const mesh::SurfaceMesh* cell : cells) {
    const double* positions = cell->positionData();
    for (int n = 0; n < cell->numNodes(); ++n) {
      lowest = std::min(lowest, positions[3 * n + 1]);
      highest = std::max(highest, positions[3 * n + 1]);
    }
  }
  CellFreeLayer layer;
  layer.lower = lowest;
  layer.upper = domain.hasUpperWall() ? domain.channelHeight() - highest : std::numeric_limits<double>::infinity();
  return layer;
}

} // namespace capsula::suspension
