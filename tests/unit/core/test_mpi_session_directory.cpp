// The private Open MPI session directory of singleton processes (MpiSessionDirectory.hpp).
#include "capsula/core/MpiSessionDirectory.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace core = capsula::core;
namespace fs = std::filesystem;

namespace {

core::EnvironmentLookup environmentOf(const std::map<std::string, std::string>& variables)
{
  return [variables](const char* name) -> const char* {
    const auto it = variables.find(name);
    return it == variables.end() ? nullptr : it->second.c_str();
  };
}

} // namespace

TEST(MpiSessionDirectory, OnlySingletonsWithoutAChosenDirectoryGetOne)
{
  EXPECT_TRUE(core::needsPrivateMpiSessionDirectory(environmentOf({})));
  EXPECT_TRUE(core::needsPrivateMpiSessionDirectory(environmentOf({{"TMPDIR", "/scratch"}})));
  // Started by mpiexec, srun or a PMI launcher: the ranks must share the launcher's directory.
  EXPECT_FALSE(core::needsPrivateMpiSessionDirectory(environmentOf({{"OMPI_COMM_WORLD_SIZE", "2"}})));
  EXPECT_FALSE(core::needsPrivateMpiSessionDirectory(environmentOf({{"PMIX_RANK", "0"}})));
  EXPECT_FALSE(core::needsPrivateMpiSessionDirectory(environmentOf({{"PMI_RANK", "0"}})));
  // The user's own choice is kept.
  EXPECT_FALSE(core::needsPrivateMpiSessionDirectory(environmentOf({{"OMPI_MCA_orte_tmpdir_base", "/tmp/mine"}})));
}

// ctest starts this executable as a singleton: the test main gave it a private directory, and
// Open MPI (already initialised) keeps its session files there rather than in the shared one.
// Run under mpiexec, the launcher's directory is used and nothing is redirected.
TEST(MpiSessionDirectory, ConcurrentSingletonsDoNotShareTheSessionDirectory)
{
  const char* chosen = std::getenv("OMPI_MCA_orte_tmpdir_base");
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr) {
    EXPECT_TRUE(chosen == nullptr || fs::path(chosen).filename().string().rfind("capsula-mpi-", 0) != 0);
    return;
  }
  ASSERT_NE(chosen, nullptr);
  const fs::path directory(chosen);
  ASSERT_TRUE(fs::is_directory(directory)) << directory;
  EXPECT_EQ(directory.filename().string().rfind("capsula-mpi-", 0), 0U) << directory;
  bool openMpiSessionInside = false;
  for (const auto& entry : fs::directory_iterator(directory)) {
    openMpiSessionInside = openMpiSessionInside || entry.path().filename().string().rfind("ompi.", 0) == 0;
  }
  EXPECT_TRUE(openMpiSessionInside) << "no ompi.* session directory in " << directory;
}

TEST(MpiSessionDirectory, RemovedAfterUse)
{
  // Seen as a fresh singleton (the variables that MPI_Init and a launcher set are cleared for
  // the object's lifetime), the object creates a directory, points Open MPI at it and
  // removes it when it goes.
  const std::vector<std::string> names = {"OMPI_MCA_orte_tmpdir_base", "OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"};
  std::map<std::string, std::string> saved;
  for (const auto& name : names) {
    if (const char* value = std::getenv(name.c_str())) {
      saved[name] = value;
      unsetenv(name.c_str());
    }
  }
  std::string path;
  {
    const core::MpiSessionDirectory directory;
    path = directory.path();
    EXPECT_FALSE(path.empty());
    EXPECT_TRUE(fs::is_directory(path)) << path;
    const char* chosen = std::getenv("OMPI_MCA_orte_tmpdir_base");
    EXPECT_EQ(std::string(chosen == nullptr ? "" : chosen), path);
  }
  EXPECT_FALSE(path.empty() || fs::exists(path)) << path;
  // A process that leaves without MPI_Finalize removes it itself, once.
  unsetenv("OMPI_MCA_orte_tmpdir_base");
  {
    core::MpiSessionDirectory directory;
    path = directory.path();
    ASSERT_TRUE(fs::is_directory(path)) << path;
    directory.remove();
    EXPECT_FALSE(fs::exists(path)) << path;
    EXPECT_TRUE(directory.path().empty());
  }
  unsetenv("OMPI_MCA_orte_tmpdir_base");
  for (const auto& [name, value] : saved) {
    setenv(name.c_str(), value.c_str(), 1);
  }
}
