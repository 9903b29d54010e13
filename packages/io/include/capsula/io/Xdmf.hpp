#pragma once
// The XDMF (version 3) sidecar that lets ParaView open a snapshot file (SnapshotFile.hpp)
// as one time series: a temporal collection with one entry per snapshot; each entry is a
// spatial collection of the snapshot's blocks, whose geometry and attributes point into
// the snapshot's group ("snapshots.h5:/snapshots/000012/cell0/positions") and whose
// topology points into its mesh version ("snapshots.h5:/mesh/000000/cell0/connectivity").
// The file name is relative, so the output directory can be moved.
#include "capsula/io/Snapshot.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace capsula::io {

/// What the XDMF needs to know of one snapshot: where it lies, shapes and names, no data.
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
  std::string group;     ///< "/snapshots/000012": <group>/<block>/positions, fields
  std::string meshGroup; ///< "/mesh/000000": <meshGroup>/<block>/connectivity
  double time = 0.0;
  std::int64_t step = 0;
  std::vector<BlockLayout> blocks;
};

SnapshotLayout layoutOf(const Snapshot& snapshot, const std::string& group, const std::string& meshGroup);

/// The XDMF document for the snapshots, in time order, of the HDF5 file `fileName`
/// (a path relative to the XDMF file).
std::string xdmfTimeSeries(const std::string& fileName, const std::vector<SnapshotLayout>& snapshots);

} // namespace capsula::io
