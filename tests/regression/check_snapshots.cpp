// check_snapshots: compares snapshot files (io/SnapshotFile.hpp) in the regression tests.
//
//   check_snapshots same FILE_A FILE_B
//       The same number of snapshots, each with the same time, step, blocks, connectivity,
//       positions and fields, bit for bit (a restarted run against the uninterrupted one).
//   check_snapshots count FILE N
//       The file holds exactly N snapshots.
//   check_snapshots folded FILE LX LZ
//       In every snapshot the mean of each cell block's ("cell<c>") nodes lies in the box
//       [0, LX) x R x [0, LZ) ('Output/Fold into box'), and at least one snapshot holds a
//       cell with nodes on both sides of a boundary or outside the box (else the test
//       proves nothing about folding whole cells).
//   check_snapshots wall-maps FILE_A BLOCK_A FILE_B BLOCK_B TOLERANCE
//       The same number of snapshots at the same times; in each, the wall grid BLOCK_A of
//       FILE_A and BLOCK_B of FILE_B have the same shape, the same nodes along the wall (x, z)
//       and the same node fields in order (names may differ: dudy on the lower wall is dudn
//       on the upper), each value within TOLERANCE (a wall's map against the other wall's
//       in the mirrored run, tests/regression/channel.cmake). Prints the largest difference.
//   check_snapshots checkpoint-time FILE T
//       The checkpoint FILE (io/Checkpoint.hpp) holds the state at time T exactly (a run
//       that failed kept its last good checkpoint).
//
// Prints what it compared; exits 0 if all agree, 1 otherwise, 2 on a usage error.
#include <capsula/core/Error.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/SnapshotFile.hpp>

#include <algorithm>
#include <cmath>
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

int folded(const std::string& file, double lx, double lz)
{
  const std::size_t count = io::readSnapshotLayouts(file).size();
  bool ok = count > 0, reachesOut = false;
  for (std::size_t k = 0; k < count; ++k) {
    const io::Snapshot snapshot = io::readSnapshot(file, k);
    for (const auto& block : snapshot.blocks) {
      if (block.name.rfind("cell", 0) != 0) {
        continue;
      }
      const std::size_t n = block.positions.size() / 3;
      double mean[3] = {0.0, 0.0, 0.0};
      for (std::size_t p = 0; p < n; ++p) {
        for (int i = 0; i < 3; ++i) {
          mean[i] += block.positions[3 * p + static_cast<std::size_t>(i)] / static_cast<double>(n);
        }
        const double x = block.positions[3 * p], z = block.positions[3 * p + 2];
        reachesOut = reachesOut || x < 0.0 || x >= lx || z < 0.0 || z >= lz;
      }
      const bool inside = mean[0] >= 0.0 && mean[0] < lx && mean[2] >= 0.0 && mean[2] < lz;
      ok = ok && inside;
      std::cout << (inside ? "ok    " : "FAIL  ") << "snapshot " << k << " (t = " << snapshot.time << ") " << block.name
                << ": node mean (" << mean[0] << ", " << mean[1] << ", " << mean[2] << ")\n";
    }
  }
  std::cout << (reachesOut ? "ok    " : "FAIL  ") << "some cell reaches across the box's boundary\n";
  return ok && reachesOut ? 0 : 1;
}

const io::SnapshotBlock* findBlock(const io::Snapshot& snapshot, const std::string& name)
{
  for (const auto& block : snapshot.blocks) {
    if (block.name == name) {
      return &block;
    }
  }
  return nullptr;
}

// The largest |a - b| over two arrays of the same length, leaving out the entries k with
// k % stride == skip when stride > 1 (one coordinate of points); HUGE_VAL if the lengths
// differ or a difference is not a number.
double largestDifference(const std::vector<double>& a, const std::vector<double>& b, std::size_t stride,
                         std::size_t skip)
{
  if (a.size() != b.size()) {
    return HUGE_VAL;
  }
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (stride > 1 && k % stride == skip) {
      continue;
    }
    const double d = std::abs(a[k] - b[k]);
    worst = d <= worst ? worst : (std::isnan(d) ? HUGE_VAL : d);
  }
  return worst;
}

int wallMaps(const std::string& fileA, const std::string& blockA, const std::string& fileB, const std::string& blockB,
             double tolerance)
{
  const std::size_t count = io::readSnapshotLayouts(fileA).size();
  const std::size_t countB = io::readSnapshotLayouts(fileB).size();
  if (count == 0 || count != countB) {
    std::cout << "FAIL  " << count << " snapshots in " << fileA << ", " << countB << " in " << fileB << "\n";
    return 1;
  }
  bool ok = true;
  for (std::size_t k = 0; k < count; ++k) {
    const io::Snapshot a = io::readSnapshot(fileA, k), b = io::readSnapshot(fileB, k);
    const io::SnapshotBlock *x = findBlock(a, blockA), *y = findBlock(b, blockB);
    if (!x || !y || a.time != b.time || x->gridShape != y->gridShape || x->nodeFields.size() != y->nodeFields.size()) {
      std::cout << "FAIL  snapshot " << k << ": no blocks '" << blockA << "' and '" << blockB
                << "' of the same shape at the same time\n";
      ok = false;
      continue;
    }
    // Along the wall only: the walls' heights differ (skip y, every third coordinate).
    const double nodes = largestDifference(x->positions, y->positions, 3, 1);
    double fields = 0.0;
    for (std::size_t f = 0; f < x->nodeFields.size(); ++f) {
      fields = std::max(fields, largestDifference(x->nodeFields[f].values, y->nodeFields[f].values, 1, 0));
    }
    const bool pass = nodes <= tolerance && fields <= tolerance;
    ok = ok && pass;
    std::cout << (pass ? "ok    " : "FAIL  ") << "snapshot " << k << " (t = " << a.time
              << "): " << x->positions.size() / 3 << " nodes, largest difference " << fields << " in the fields, "
              << nodes << " in x and z (allowed " << tolerance << ")\n";
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
    if (mode == "folded" && argc == 5) {
      return folded(argv[2], std::atof(argv[3]), std::atof(argv[4]));
    }
    if (mode == "wall-maps" && argc == 7) {
      return wallMaps(argv[2], argv[3], argv[4], argv[5], std::atof(argv[6]));
    }
    if (mode == "checkpoint-time" && argc == 4) {
      const double time = io::readCheckpoint(argv[2]).time;
      const double expected = std::atof(argv[3]);
      std::cout << (time == expected ? "ok    " : "FAIL  ") << "checkpoint at t = " << time << ", expected " << expected
                << "\n";
      return time == expected ? 0 : 1;
    }
    std::cerr << "usage: check_snapshots same FILE_A FILE_B | count FILE N | folded FILE LX LZ\n"
                 "       | wall-maps FILE_A BLOCK_A FILE_B BLOCK_B TOLERANCE | checkpoint-time FILE T\n";
    return 2;
  } catch (const capsula::core::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
