#pragma once
// A time series of snapshots in an output directory:
//
//   <dir>/<base>_000000.h5, <base>_000001.h5, ...   one self-contained file per snapshot
//   <dir>/<base>.xdmf                                the ParaView entry point
//
// Why one file per snapshot: each is written to a temporary name and renamed, and the
// XDMF is rewritten atomically afterwards, so at every instant the XDMF references only
// complete files, and a crash can neither corrupt earlier snapshots (as a crash inside a
// single growing HDF5 file can) nor leave a half-written one. Restart drops the snapshots
// written after the checkpoint.
//
// Serial: call from one rank (gather to it first).
#include "capsula/io/Snapshot.hpp"
#include "capsula/io/Xdmf.hpp"

#include <string>
#include <vector>

namespace capsula::io {

class SnapshotSeries {
public:
  /// A new series. Snapshot files of an earlier series with the same base name in
  /// `directory` are removed (they would otherwise mix with this run's). `baseName` must
  /// be letters, digits, '_', '-' or '.'.
  SnapshotSeries(std::string directory, std::string baseName);

  /// Continues the series after a restart from a checkpoint at `checkpointTime`: keeps the
  /// snapshots with time <= checkpointTime, deletes later ones (written after the
  /// checkpoint by the run that stopped) and rewrites the XDMF. Throws core::IoError
  /// naming a file that cannot be read.
  static SnapshotSeries resume(std::string directory, std::string baseName, double checkpointTime);

  /// Writes the next snapshot file and the updated XDMF; returns the snapshot's path.
  std::string write(const Snapshot& snapshot);

  std::size_t size() const { return layouts_.size(); }
  const std::vector<SnapshotLayout>& layouts() const { return layouts_; }
  std::string xdmfPath() const;
  /// Path of snapshot `index` (0-based).
  std::string snapshotPath(std::size_t index) const;

private:
  SnapshotSeries() = default;
  struct ExistingFile {
    std::size_t index;
    std::string path;
  };
  std::vector<ExistingFile> existingFiles() const;
  void writeXdmf() const;

  std::string directory_;
  std::string baseName_;
  std::vector<SnapshotLayout> layouts_;
};

} // namespace capsula::io
