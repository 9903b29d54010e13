#pragma once
// Checkpoint/restart files (HDF5):
//
//   /                 attributes format = "Capsula checkpoint", version, time, step, step size,
//                     application (the app that wrote it; absent in older files)
//   /deck             the validated deck as XML text (what the run was started with)
//   /arrays/<name>    named float64 vectors (the state, ...)
//   /reals            attributes: named float64 scalars
//   /integers         attributes: named int64 scalars
//
// Doubles are stored as IEEE float64 and read back bit for bit. The file is written to a
// temporary name, flushed to disk and renamed, so the previous checkpoint survives any
// crash during writing. Serial: call from one rank.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace capsula::io {

struct Checkpoint {
  double time = 0.0;
  std::int64_t step = 0;
  double stepSize = 0.0;
  std::string application; ///< "cell3d", ...; "" if not recorded
  std::string deckXml;
  std::map<std::string, std::vector<double>> arrays;
  std::map<std::string, double> reals;
  std::map<std::string, std::int64_t> integers;
};

/// Writes `checkpoint` to `path` atomically. Names must not contain '/' and must not be
/// empty. Throws core::IoError naming the file.
void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint);

/// Reads and validates a checkpoint. Throws core::IoError naming the file if it is
/// missing, not an HDF5 file (truncated, corrupt), not a Capsula checkpoint, of another
/// format version, or lacks an entry.
Checkpoint readCheckpoint(const std::string& path);

} // namespace capsula::io
