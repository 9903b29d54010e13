#pragma once
// One snapshot in one self-contained HDF5 file:
//
//   /                  attributes format = "Capsula snapshot", version, time, step
//   /<block>/          attributes topology (XDMF name), dimension,
//                      nodes_per_polyline | grid_shape
//   /<block>/positions        nodes x dimension        float64
//   /<block>/connectivity     elements x nodes/element int64 (not for grids)
//   /<block>/node_fields/<f>  nodes (1 component) or nodes x components
//   /<block>/cell_fields/<f>  elements (1 component) or elements x components
//
// Each file holds its own topology, so meshes whose connectivity changes (adaption)
// are stored correctly. The file is written to a temporary name, flushed to disk and
// renamed: a crash never leaves a partial snapshot under the final name.
//
// Serial: call from one rank (gather to it first); the parallel HDF5 library is used
// with its default POSIX driver.
#include "capsula/io/Snapshot.hpp"

#include <string>

namespace capsula::io {

/// Writes `snapshot` to `path` atomically. Throws core::IoError naming the file.
void writeSnapshotFile(const std::string& path, const Snapshot& snapshot);

/// Reads a file written by writeSnapshotFile. Throws core::IoError naming the file if it
/// is missing, not HDF5, or not a Capsula snapshot.
Snapshot readSnapshotFile(const std::string& path);

} // namespace capsula::io
