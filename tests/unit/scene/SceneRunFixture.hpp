#pragma once
// A test fixture for whole scene runs: a scratch directory per test (removed afterwards),
// runScene into a folder of it (optionally restarting from another), and reading back
// its files.
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/scene/SceneRun.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace capsula::scene::testing {

class SceneRunFixture : public ::testing::Test {
protected:
  void SetUp() override
  {
    root_ = std::filesystem::temp_directory_path() /
            ("capsula-scene-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
  }
  void TearDown() override { std::filesystem::remove_all(root_); }

  /// runScene(deck) with its output in `directory` (restarting from `restart` if given).
  SceneRunResult run(const Teuchos::ParameterList& deck, const std::string& directory,
                     const std::string& restart = "")
  {
    static const auto kernels = operators::builtInKernels();
    SceneRunOptions options;
    options.application = "test";
    options.outputDirectory = (root_ / directory).string();
    if (!restart.empty()) {
      options.restartDirectory = (root_ / restart).string();
    }
    return runScene(deck, Tpetra::getDefaultComm(), options, kernels);
  }

  /// The text of `file` (relative to the scratch directory).
  std::string read(const std::string& file) const
  {
    std::ifstream in(root_ / file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  std::filesystem::path root_;
};

} // namespace capsula::scene::testing
