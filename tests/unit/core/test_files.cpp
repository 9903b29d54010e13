// Atomic output and writable-directory checks.
#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

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
