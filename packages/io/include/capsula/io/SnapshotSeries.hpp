#pragma once
// A run's time series of snapshots in its output directory:
//
//   <dir>/<base>.h5     every snapshot, the mesh versions and the wall fields
//                       (one HDF5 file, layout in SnapshotFile.hpp)
//   <dir>/<base>.xdmf   the ParaView entry point: a temporal collection over <base>.h5
//
// Why this order of writes, and what a failure costs:
// - A new series creates <base>.h5 (no snapshot yet) atomically: a temporary file,
//   fsync, rename; then the XDMF.
// - write() appends the snapshot to <base>.h5 (the file is closed between snapshots; an
//   append opens it, writes through an undo journal, links the new group last, flushes,
//   closes and fsyncs: see SnapshotFile.hpp) and only then rewrites the XDMF atomically
//   (write-then-rename). So the XDMF never names a snapshot that is not complete on disk,
//   and a run that dies at any point leaves a file that holds every snapshot completed
//   before, possibly after the next writer has undone the interrupted append (the
//   journal <base>.h5.undo exists only while an append runs or after one was
//   interrupted), and an XDMF that is at most one snapshot short.
// - resume() (restart from a checkpoint at time t) first undoes an interrupted append,
//   then keeps the snapshots with time <= t, removes the ones the stopped run wrote after
//   its checkpoint, and rewrites the XDMF, so a restarted run appends to the same file
//   and ends with the series of an uninterrupted run.
//
// Serial: call from one rank (gather to it first).
#include "capsula/io/Snapshot.hpp"
#include "capsula/io/Xdmf.hpp"

#include <string>
#include <vector>

namespace capsula::io {

class SnapshotSeries {
public:
  /// A new, empty series: creates <directory>/<baseName>.h5 and .xdmf, replacing those of
  /// an earlier run. `baseName` must be letters, digits, '_', '-' or '.'. Throws
  /// core::IoError naming a directory or file that cannot be written.
  SnapshotSeries(std::string directory, std::string baseName);

  /// Continues the series after a restart from a checkpoint at `checkpointTime`: keeps the
  /// snapshots with time <= checkpointTime, removes later ones (written after the
  /// checkpoint by the run that stopped) and rewrites the XDMF. If `sourceDirectory` is
  /// given and differs from `directory` (a restart that writes elsewhere), the source's
  /// file is first copied over, so the new directory holds the whole series. Without a
  /// file to continue (the stopped run wrote no snapshot) a new series starts. Throws
  /// core::IoError naming a file that cannot be read (with what to do about it).
  static SnapshotSeries resume(std::string directory, std::string baseName, double checkpointTime,
                               const std::string& sourceDirectory = "");

  /// Appends the snapshot, then updates the XDMF; returns its index (0-based).
  std::size_t write(const Snapshot& snapshot);

  std::size_t size() const { return layouts_.size(); }
  const std::vector<SnapshotLayout>& layouts() const { return layouts_; }
  std::string filePath() const;
  std::string xdmfPath() const;

private:
  SnapshotSeries(std::string directory, std::string baseName, bool create);
  void writeXdmf() const;

  std::string directory_;
  std::string baseName_;
  std::vector<SnapshotLayout> layouts_;
};

} // namespace capsula::io
