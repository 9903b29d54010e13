#pragma once
// Whole scene runs in the tests: small validated run decks (the scene tests' spheres with
// the keys of a short run), and a fixture with a scratch directory per test (removed
// afterwards) that runs a deck into a folder of it (optionally restarting from another)
// and reads its files back.
#include "SceneTestDecks.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/run/SceneRun.hpp>
#include <capsula/run/SceneRunDeck.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace capsula::run::testing {

/// scene::testing::sphereDeck with a short run (to t = 0.2, outputs every 0.1, RKF45 at a
/// loose tolerance), the other keys at their defaults unless `tweak` changes them. Validated
/// as a cell3d deck.
template <typename Tweak>
Teuchos::RCP<Teuchos::ParameterList> smallDeck(int level, double height, bool wall, Tweak&& tweak)
{
  auto deck = scene::testing::sphereDeck(level, height, wall);
  deck->sublist("Time integration").set("End time", 0.2);
  deck->sublist("Time integration").set("Initial step", 0.02);
  deck->sublist("Time integration").set("Tolerance", 1e-4);
  deck->sublist("Output").set("Interval", 0.1);
  tweak(*deck);
  core::validateDeck(*deck, *validSceneRunParameters(*deck, "test"), "test deck");
  return deck;
}

inline Teuchos::RCP<Teuchos::ParameterList> smallDeck(int level, double height, bool wall)
{
  return smallDeck(level, height, wall, [](Teuchos::ParameterList&) {});
}

class SceneRunFixture : public ::testing::Test {
protected:
  void SetUp() override
  {
    root_ = std::filesystem::temp_directory_path() / ("capsula-scene-" + std::to_string(::getpid()) + "-" +
                                                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
  }
  void TearDown() override { std::filesystem::remove_all(root_); }

  /// runScene(deck) with its output in `directory` (restarting from `restart` if given).
  SceneRunResult run(const Teuchos::ParameterList& deck, const std::string& directory, const std::string& restart = "")
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

} // namespace capsula::run::testing
