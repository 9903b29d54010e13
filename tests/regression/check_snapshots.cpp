// check_snapshots: compares snapshot files (io/SnapshotFile.hpp) in the regression tests.
//
//   check_snapshots same FILE_A FILE_B
//       The same number of snapshots, each with the same time, step, blocks, connectivity,
//       positions and fields, bit for bit (a restarted run against the uninterrupted one).
//   check_snapshots count FILE N
//       The file holds exactly N snapshots.
//   check_snapshots checkpoint-time FILE T
//       The checkpoint FILE (io/Checkpoint.hpp) holds the state at time T exactly (a run
//       that failed kept its last good checkpoint).
//
// Prints what it compared; exits 0 if all agree, 1 otherwise, 2 on a usage error.
#include <capsula/core/Error.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/SnapshotFile.hpp>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace io = capsula::io;

bool sameFields(const std::vector<io::Field>& a, const std::vector<io::Field>& b)
{
  if (a.size() != b.size()) {
    return false;
  }
  for (std::size_t f = 0; f < a.size(); ++f) {
    if (a[f].name != b[f].name || a[f].components != b[f].components || a[f].values != b[f].values) {
      return false;
    }
  }
  return true;
}

/// "" if the snapshots agree bit for bit, else what differs.
std::string difference(const io::Snapshot& a, const io::Snapshot& b)
{
  if (a.time != b.time || a.step != b.step) {
    return "time or step";
  }
  if (a.blocks.size() != b.blocks.size()) {
    return "number of blocks";
  }
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const auto &x = a.blocks[i], &y = b.blocks[i];
    if (x.name != y.name || x.topology != y.topology || x.connectivity != y.connectivity ||
        x.gridShape != y.gridShape) {
      return "mesh of block '" + x.name + "'";
    }
    if (x.positions != y.positions) {
      return "positions of block '" + x.name + "'";
    }
    if (!sameFields(x.nodeFields, y.nodeFields) || !sameFields(x.cellFields, y.cellFields)) {
      return "fields of block '" + x.name + "'";
    }
  }
  return "";
}

int same(const std::string& fileA, const std::string& fileB)
{
  const std::size_t count = io::readSnapshotLayouts(fileA).size();
  const std::size_t countB = io::readSnapshotLayouts(fileB).size();
  if (count != countB) {
    std::cout << "FAIL  " << count << " snapshots in " << fileA << ", " << countB << " in " << fileB << "\n";
    return 1;
  }
  bool ok = true;
  for (std::size_t k = 0; k < count; ++k) {
    const io::Snapshot a = io::readSnapshot(fileA, k), b = io::readSnapshot(fileB, k);
    const std::string differs = difference(a, b);
    ok = ok && differs.empty();
    std::cout << (differs.empty() ? "ok    " : "FAIL  ") << "snapshot " << k << " (t = " << a.time << ")"
              << (differs.empty() ? "" : ": the " + differs + " differ") << "\n";
  }
  return ok ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "same" && argc == 4) {
      return same(argv[2], argv[3]);
    }
    if (mode == "count" && argc == 4) {
      const std::size_t count = io::readSnapshotLayouts(argv[2]).size();
      const auto expected = static_cast<std::size_t>(std::atoll(argv[3]));
      std::cout << (count == expected ? "ok    " : "FAIL  ") << count << " snapshots, expected " << expected << "\n";
      return count == expected ? 0 : 1;
    }
    if (mode == "checkpoint-time" && argc == 4) {
      const double time = io::readCheckpoint(argv[2]).time;
      const double expected = std::atof(argv[3]);
      std::cout << (time == expected ? "ok    " : "FAIL  ") << "checkpoint at t = " << time << ", expected " << expected
                << "\n";
      return time == expected ? 0 : 1;
    }
    std::cerr << "usage: check_snapshots same FILE_A FILE_B | count FILE N | checkpoint-time FILE T\n";
    return 2;
  } catch (const capsula::core::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
