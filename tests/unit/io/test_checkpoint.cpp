// Checkpoints: bit-for-bit round trip, atomic replacement, and clear errors for missing,
// truncated, foreign or unwritable files.
#include "TemporaryDirectory.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/io/Checkpoint.hpp"
#include "capsula/io/SnapshotFile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

namespace io = capsula::io;
namespace core = capsula::core;
using io::testing::TemporaryDirectory;

namespace {

bool bitwiseEqual(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

bool bitwiseEqual(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

io::Checkpoint sampleCheckpoint()
{
  io::Checkpoint c;
  c.time = 3.2000000000000006;
  c.step = 123456789012LL;
  c.stepSize = std::nextafter(1e-3, 1.0);
  c.deckXml = "<ParameterList name=\"Capsula\">\n  <Parameter name=\"Title\" type=\"string\" "
              "value=\"a &amp; b &lt; c, \xc2\xb5m\"/>\n</ParameterList>\n";
  std::mt19937_64 random(2024);
  std::vector<double> state(30000);
  for (auto& x : state) {
    std::uint64_t bits = random();
    std::memcpy(&x, &bits, sizeof(double)); // every bit pattern, NaN payloads included
  }
  state[0] = -0.0;
  state[1] = std::numeric_limits<double>::denorm_min();
  state[2] = std::numeric_limits<double>::infinity();
  c.arrays["state"] = state;
  c.arrays["first stage derivative"] = {1.0, -2.0, 1.0 / 3.0};
  c.arrays["empty"] = {};
  c.reals["previous error norm"] = 0.1;
  c.reals["smallest step"] = std::numeric_limits<double>::infinity();
  c.integers["accepted steps"] = std::numeric_limits<std::int64_t>::max();
  c.integers["rejected steps"] = -1;
  return c;
}

} // namespace

TEST(Checkpoint, RoundTripIsBitForBit)
{
  TemporaryDirectory dir("checkpoint_roundtrip");
  const std::string path = dir.file("checkpoint.h5");
  const io::Checkpoint c = sampleCheckpoint();
  io::writeCheckpoint(path, c);
  EXPECT_EQ(dir.entryCount(), 1u);
  const io::Checkpoint r = io::readCheckpoint(path);
  EXPECT_TRUE(bitwiseEqual(r.time, c.time));
  EXPECT_EQ(r.step, c.step);
  EXPECT_TRUE(bitwiseEqual(r.stepSize, c.stepSize));
  EXPECT_EQ(r.deckXml, c.deckXml);
  ASSERT_EQ(r.arrays.size(), c.arrays.size());
  for (const auto& [name, values] : c.arrays) {
    ASSERT_EQ(r.arrays.count(name), 1u) << name;
    EXPECT_TRUE(bitwiseEqual(r.arrays.at(name), values)) << name;
  }
  ASSERT_EQ(r.reals.size(), c.reals.size());
  for (const auto& [name, value] : c.reals) {
    EXPECT_TRUE(bitwiseEqual(r.reals.at(name), value)) << name;
  }
  EXPECT_EQ(r.integers, c.integers);
}

TEST(Checkpoint, EmptyDeckAndNoEntriesRoundTrip)
{
  TemporaryDirectory dir("checkpoint_empty");
  const std::string path = dir.file("checkpoint.h5");
  io::writeCheckpoint(path, io::Checkpoint{});
  const io::Checkpoint r = io::readCheckpoint(path);
  EXPECT_EQ(r.deckXml, "");
  EXPECT_TRUE(r.arrays.empty());
  EXPECT_TRUE(r.reals.empty());
  EXPECT_TRUE(r.integers.empty());
}

TEST(Checkpoint, AFailedWriteKeepsThePreviousCheckpoint)
{
  TemporaryDirectory dir("checkpoint_atomic");
  const std::string path = dir.file("checkpoint.h5");
  io::writeCheckpoint(path, sampleCheckpoint());
  io::Checkpoint bad = sampleCheckpoint();
  bad.time = 99.0;
  bad.arrays["a/b"] = {1.0};
  try {
    io::writeCheckpoint(path, bad);
    FAIL() << "an array name with '/' was written";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), path)) << e.what();
    EXPECT_TRUE(io::testing::contains(e.what(), "'a/b'")) << e.what();
  }
  EXPECT_EQ(io::readCheckpoint(path).time, sampleCheckpoint().time);
  EXPECT_EQ(dir.entryCount(), 1u);
}

TEST(Checkpoint, MissingTruncatedOrForeignFilesAreNamed)
{
  TemporaryDirectory dir("checkpoint_corrupt");
  const std::string good = dir.file("good.h5");
  io::writeCheckpoint(good, sampleCheckpoint());

  const std::string truncated = dir.file("truncated.h5");
  std::filesystem::copy_file(good, truncated);
  std::filesystem::resize_file(truncated, std::filesystem::file_size(good) / 2);

  const std::string garbage = dir.file("garbage.h5");
  std::ofstream(garbage) << "this is not HDF5";

  const std::string snapshot = dir.file("snapshot.h5");
  io::createSnapshotFile(snapshot);

  for (const auto& path : {dir.file("missing.h5"), truncated, garbage, snapshot}) {
    try {
      io::readCheckpoint(path);
      FAIL() << path << " was read as a checkpoint";
    } catch (const core::IoError& e) {
      EXPECT_TRUE(io::testing::contains(e.what(), "'" + path + "'")) << e.what();
      std::printf("%s\n", e.what());
    }
  }
}

TEST(Checkpoint, UnwritableDirectoryIsNamed)
{
  TemporaryDirectory dir("checkpoint_unwritable");
  std::ofstream(dir.file("a-file")) << "x";
  const std::string path = dir.file("a-file") + "/checkpoint.h5";
  try {
    io::writeCheckpoint(path, sampleCheckpoint());
    FAIL() << "a checkpoint below a regular file was written";
  } catch (const core::IoError& e) {
    EXPECT_TRUE(io::testing::contains(e.what(), path)) << e.what();
  }
}
