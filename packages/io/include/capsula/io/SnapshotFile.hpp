#pragma once
// A whole time series of snapshots in one HDF5 file:
//
//   /                                     attributes format = "Capsula snapshots", version
//   /mesh/<m>/                            mesh version m = 000000, 000001, ...
//   /mesh/<m>/<block>/                    attributes topology (XDMF name), dimension, nodes,
//                                         nodes_per_polyline | grid_shape
//   /mesh/<m>/<block>/connectivity        elements x nodes/element int64 (not for grids)
//   /snapshots/<k>/                       snapshot k = 000000, 000001, ...: attributes
//                                         time, step, mesh (its mesh version m)
//   /snapshots/<k>/<block>/positions      nodes x dimension float64 (the mesh moves)
//   /snapshots/<k>/<block>/node_fields/<f>  nodes (1 component) or nodes x components
//   /snapshots/<k>/<block>/cell_fields/<f>  elements (1 component) or elements x components
//
// What does not change between snapshots (the blocks, their topology and connectivity) is
// written once, as a mesh version; a snapshot whose blocks or connectivity differ from the
// latest version (a remeshed cell, say) gets a new version, so adaptive meshes are stored
// correctly.
//
// Appending is the one write that changes an existing file, and HDF5 cannot make it
// atomic: new objects go past the end of the file, but linking them in rewrites metadata
// blocks in place, and a writer killed in the middle of that leaves the file unreadable.
// (Copying the whole file for every snapshot would make it atomic at a cost quadratic in
// the number of snapshots.) So every write into an existing file goes through an undo
// journal (src/UndoJournal.hpp): before a byte that existed when the file was opened is
// overwritten, its old value is saved to <file>.undo and synced; a clean close syncs the
// file and then deletes the journal. The next writer (appendSnapshot, truncateSnapshots,
// SnapshotSeries::resume) finds a journal left by a writer that died, writes the old
// bytes back and cuts what was appended: the file is again exactly what it was after the
// last complete append. Besides, the file stays closed between appends, and a snapshot
// (and a new mesh version) is built as an anonymous group that is linked in only once
// complete, so an append that fails with an error (disk full) leaves no partial snapshot
// either. The file is written in HDF5's oldest compatible format (superblock version 0),
// which has no "open for writing" flag, so a writer that dies never leaves it locked.
//
// Serial: call from one rank (gather to it first); the parallel HDF5 library is used
// with POSIX drivers only (its default one for reading, the journalling one for writing).
#include "capsula/io/Snapshot.hpp"
#include "capsula/io/Xdmf.hpp"

#include <string>
#include <vector>

namespace capsula::io {

/// Creates `path` as a snapshot file holding no snapshot, atomically (a temporary file,
/// fsync, rename), replacing any file there. Throws core::IoError naming the file.
void createSnapshotFile(const std::string& path);

/// If a writer died while changing `path` (its undo journal exists), restores the file to
/// its state after the last complete change; returns whether it did. Writers call this
/// themselves; readers do not (they may run while a writer works).
bool undoInterruptedAppend(const std::string& path);

/// Appends `snapshot` as the next snapshot of the file (and a new mesh version if its
/// blocks or connectivity differ from the latest one); returns its layout. Refuses an
/// inconsistent snapshot (core::Error naming the block) before touching the file.
/// Throws core::IoError naming the file if it cannot be written.
SnapshotLayout appendSnapshot(const std::string& path, const Snapshot& snapshot);

/// The snapshots in the file, in order: where they lie and their shapes, no field data.
/// Throws core::IoError naming the file if it is missing, not HDF5, not a Capsula
/// snapshot file, or inconsistent.
std::vector<SnapshotLayout> readSnapshotLayouts(const std::string& path);

/// Snapshot `index` (0-based) with its connectivity from its mesh version.
Snapshot readSnapshot(const std::string& path, std::size_t index);

/// Keeps the first `count` snapshots and the mesh versions they use; removes the rest. The
/// kept ones are copied into a new file that then replaces `path` atomically: HDF5 never
/// gives back the space of objects removed in place, so a file cut there would keep the
/// size of every snapshot a restart ever dropped.
void truncateSnapshots(const std::string& path, std::size_t count);

/// "000012": the group name of snapshot or mesh version 12.
std::string snapshotGroupName(std::size_t index);

} // namespace capsula::io
