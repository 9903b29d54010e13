// Atomic output and writable-directory checks.
#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace core = capsula::core;
namespace fs = std::filesystem;

namespace {
std::string readAll(const fs::path& p)
{
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path freshDirectory(const std::string& name)
{
  const fs::path dir = fs::temp_directory_path() / ("capsula_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}
} // namespace

TEST(Files, AtomicWriteReplacesAndLeavesNoTemporary)
{
  const auto dir = freshDirectory("atomic");
  core::ensureWritableDirectory(dir.string());
  const auto file = dir / "metrics.csv";
  core::writeFileAtomically(file.string(), [](std::ostream& out) { out << "first\n"; });
  core::writeFileAtomically(file.string(), [](std::ostream& out) { out << "second\n"; });
  EXPECT_EQ(readAll(file), "second\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

TEST(Files, FailedWriteKeepsThePreviousFile)
{
  const auto dir = freshDirectory("keep");
  core::ensureWritableDirectory(dir.string());
  const auto file = dir / "summary.json";
  core::writeFileAtomically(file.string(), [](std::ostream& out) { out << "good\n"; });
  EXPECT_THROW(core::writeFileAtomically(file.string(),
                                         [](std::ostream& out) {
                                           out << "partial";
                                           throw core::NumericalError("state became NaN");
                                         }),
               core::NumericalError);
  EXPECT_EQ(readAll(file), "good\n");
  fs::remove_all(dir);
}

TEST(Files, UnwritableOutputDirectoryIsNamed)
{
  // A path below a regular file cannot be created, even by root.
  const auto dir = freshDirectory("blocked");
  fs::create_directories(dir);
  const auto blocker = dir / "a-file";
  std::ofstream(blocker) << "x";
  const std::string target = (blocker / "out").string();
  try {
    core::ensureWritableDirectory(target);
    FAIL() << "a directory below a file was accepted";
  } catch (const core::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("'" + target + "'"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(Files, StaleTemporaryFilesOfDeadProcessesAreRemoved)
{
  const auto dir = freshDirectory("stale");
  core::ensureWritableDirectory(dir.string());
  pid_t dead = 4000000; // a process id no process has now
  while (fs::exists("/proc/" + std::to_string(dead))) {
    --dead;
  }
  const std::vector<std::string> names{"checkpoint.h5.tmp." + std::to_string(dead),           // removed
                                       "summary.json.tmp." + std::to_string(::getppid()),     // a live process
                                       "metrics.csv", "notes.tmp.txt", "checkpoint.h5.tmp."}; // not temporaries
  for (const auto& name : names) {
    std::ofstream(dir / name) << "x";
  }
  EXPECT_EQ(core::removeStaleTemporaryFiles(dir.string()), std::vector<std::string>{names[0]});
  for (std::size_t i = 1; i < names.size(); ++i) {
    EXPECT_TRUE(fs::exists(dir / names[i])) << names[i];
  }
  fs::remove_all(dir);
}

TEST(Files, OverwriteInPlaceOnlyWithinTheFilesSize)
{
  const auto dir = freshDirectory("in_place");
  core::ensureWritableDirectory(dir.string());
  const auto file = dir / "summary.json";
  std::ofstream(file) << "{\"status\": \"running\", \"time\": 1}\n";
  EXPECT_TRUE(core::overwriteInPlace(file.string(), "{\"status\": \"failed\"}\n"));
  EXPECT_EQ(readAll(file), "{\"status\": \"failed\"}\n");
  EXPECT_FALSE(core::overwriteInPlace(file.string(), std::string(100, 'x')));
  EXPECT_EQ(readAll(file), "{\"status\": \"failed\"}\n");
  EXPECT_FALSE(core::overwriteInPlace((dir / "missing.json").string(), "{}"));
  fs::remove_all(dir);
}

TEST(Files, DiskFullAdviceOnlyForAFullDisk)
{
  EXPECT_NE(core::diskFullAdvice(ENOSPC).find("The disk is full"), std::string::npos);
  EXPECT_NE(core::diskFullAdvice(EDQUOT).find("--output DIR"), std::string::npos);
  EXPECT_EQ(core::diskFullAdvice(EACCES), "");
  EXPECT_EQ(core::diskFullAdvice(0), "");
}
