#pragma once
// The XDMF (version 3) sidecar that lets ParaView open a series of snapshot files as one
// time series: a temporal collection with one entry per snapshot file; each entry is a
// spatial collection of the file's blocks, whose topology, geometry and attributes point
// into the HDF5 file ("snap_000012.h5:/cell0/positions"). File names are relative, so
// the output directory can be moved.
#include "capsula/io/Snapshot.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace capsula::io {

/// What the XDMF needs to know of one snapshot file: shapes and names, no data.
struct SnapshotLayout {
  struct FieldLayout {
    std::string name;
    int components = 1;
  };
  struct BlockLayout {
    std::string name;
    Topology topology = Topology::QuadraticTriangles;
    int dimension = 3;
    std::size_t nodes = 0;
    std::size_t cells = 0;
    std::size_t nodesPerCell = 0;
    std::array<std::int64_t, 2> gridShape{0, 0};
    std::vector<FieldLayout> nodeFields;
    std::vector<FieldLayout> cellFields;
  };
  std::string fileName;   ///< relative to the XDMF file
  double time = 0.0;
  std::int64_t step = 0;
  std::vector<BlockLayout> blocks;
};

SnapshotLayout layoutOf(const Snapshot& snapshot, const std::string& fileName);

/// The XDMF document for the snapshots in time order.
std::string xdmfTimeSeries(const std::vector<SnapshotLayout>& snapshots);

} // namespace capsula::io
