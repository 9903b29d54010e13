#pragma once
// One output instant of a run, as it goes into an HDF5 snapshot file: a list of blocks
// (each cell surface, a 2D contour, a wall grid...), each with its own topology, node
// positions (the mesh moves, so positions are stored at every snapshot) and named fields
// at the nodes or on the elements.
//
// Topologies and their XDMF names:
//   QuadraticTriangles  "Triangle_6": 6 nodes per element in the order
//                       v0, v1, v2, m01, m12, m20 (corners counter-clockwise seen from
//                       outside, then the midside nodes of edges 0-1, 1-2, 2-0). ParaView's
//                       XDMF readers map Triangle_6 onto VTK_QUADRATIC_TRIANGLE without
//                       reordering, and this is VTK's order; it is also the thesis's order
//                       (eq 3.19: nodes 4, 5, 6 on edges 1-2, 2-3, 3-1) used by capsula::mesh.
//   Polylines           "Polyline": `nodesPerPolyline` nodes per polyline (a closed 2D
//                       contour of n nodes is one polyline 0, 1, ..., n-1, 0).
//   StructuredGrid      "2DSMesh": a logically rectangular sheet of gridShape[0] x
//                       gridShape[1] nodes, row-major (index j of gridShape[1] fastest),
//                       no connectivity; e.g. the wall grid of a wall-shear-stress map.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace capsula::io {

enum class Topology { QuadraticTriangles, Polylines, StructuredGrid };

/// Block, field and file base names: non-empty, letters, digits, '_', '-', '.' (safe
/// as HDF5 names, XML attribute values and file names).
bool isValidOutputName(const std::string& name);

/// "Triangle_6", "Polyline", "2DSMesh".
std::string xdmfTopologyName(Topology topology);

/// Values of a field, `components` per node or per element, row-major
/// (values.size() = count * components).
struct Field {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

struct SnapshotBlock {
  std::string name; ///< letters, digits, '_', '-', '.'
  Topology topology = Topology::QuadraticTriangles;
  int dimension = 3;                           ///< coordinates per node: 3 (XYZ) or 2 (XY)
  std::vector<double> positions;               ///< nodes x dimension, row-major
  std::vector<std::int64_t> connectivity;      ///< elements x nodes per element (none for grids)
  int nodesPerPolyline = 0;                    ///< Polylines only
  std::array<std::int64_t, 2> gridShape{0, 0}; ///< StructuredGrid only
  std::vector<Field> nodeFields;
  std::vector<Field> cellFields;

  std::size_t nodeCount() const;
  std::size_t cellCount() const;
  std::size_t nodesPerCell() const;
  /// Throws core::Error naming the block and what is inconsistent (sizes, indices,
  /// names) before anything is written.
  void checkConsistency() const;
};

struct Snapshot {
  double time = 0.0;
  std::int64_t step = 0;
  std::vector<SnapshotBlock> blocks;
};

} // namespace capsula::io
