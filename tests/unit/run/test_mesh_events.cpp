// Scene runs whose state is more than the node positions, and their restarts: mesh
// regularisation (the reference shapes the redistributions left), mesh adaption (the
// refined meshes) and GMRES's warm start (the last solutions): a restarted run repeats the
// uninterrupted one bit for bit.
#include "SceneRunFixture.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/run/SceneOutputSettings.hpp>
#include <capsula/scene/SceneDescription.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

namespace core = capsula::core;
namespace run = capsula::run;
namespace scene = capsula::scene;
using run::testing::smallDeck;

auto enabled(double trigger)
{
  return [trigger](Teuchos::ParameterList& d) {
    d.sublist("Mesh regularisation").set("Enabled", true);
    d.sublist("Mesh regularisation").set("Minimum angle", trigger);
  };
}

} // namespace

TEST(MeshRegularisation, TriggerMustBeAboveTheStopAngle)
{
  try {
    const auto deck = smallDeck(1, 0.0, false, [](Teuchos::ParameterList& d) {
      enabled(4.0)(d); // below the default stop at 5 degrees
    });
    run::readSceneOutputSettings(*deck, scene::describeScene(*deck));
    FAIL() << "accepted a trigger below the stop angle";
  } catch (const core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Mesh regularisation/Minimum angle"), std::string::npos) << what;
    EXPECT_NE(what.find("Output/Stability/Minimum angle"), std::string::npos) << what;
  }
}

class MeshRegularisationRun : public run::testing::SceneRunFixture {};

// The redistributions of a run happen again, at the same steps, after a restart: the
// checkpoint carries the reference shapes they left. Free shear at Ca = 0.9, level 1 with
// a trigger of 53 degrees, so that the cell is redistributed before and after the split
// (at t = 0.2, an output time: 2 x 0.1 is exact in binary).
TEST_F(MeshRegularisationRun, RestartReproducesTheRunBitForBit)
{
  const auto tweak = [](double end) {
    return [end](Teuchos::ParameterList& d) {
      enabled(53.0)(d);
      d.sublist("Flow").set("Capillary number", 0.9);
      d.sublist("Time integration").set("End time", end);
      d.sublist("Output").set("Snapshots", false);
    };
  };
  run(*smallDeck(1, 0.0, false, tweak(0.6)), "whole");
  const std::string summary = read("whole/summary.json");
  const auto at = summary.find("\"mesh regularisations\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GE(std::stoi(summary.substr(at + 24)), 2);

  run(*smallDeck(1, 0.0, false, tweak(0.2)), "split");
  const std::string first = read("split/summary.json");
  const auto early = first.find("\"mesh regularisations\": ");
  ASSERT_NE(early, std::string::npos);
  EXPECT_GE(std::stoi(first.substr(early + 24)), 1); // some before the split
  run(*smallDeck(1, 0.0, false, tweak(0.6)), "split", "split");
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
}

// Mesh adaption during a run: the cell is refined where it curves (its element count grows
// and the snapshots get a new mesh version), and a restart from a checkpoint written after
// a refinement continues on the refined mesh, bit for bit. Level 1 in free shear at
// Ca = 0.9, threshold 0.17 (the level-1 sphere's elements start at Q = 0.157), checked
// every 2 steps.
TEST_F(MeshRegularisationRun, AdaptionRefinesDuringTheRunAndRestartsBitForBit)
{
  const auto tweak = [](double end) {
    return [end](Teuchos::ParameterList& d) {
      d.sublist("Mesh adaption").set("Enabled", true);
      d.sublist("Mesh adaption").set("Threshold", 0.17);
      d.sublist("Mesh adaption").set("Check interval", 2);
      d.sublist("Flow").set("Capillary number", 0.9);
      d.sublist("Time integration").set("End time", end);
    };
  };
  run(*smallDeck(1, 0.0, false, tweak(0.4)), "whole");
  const std::string summary = read("whole/summary.json");
  const auto at = summary.find("\"mesh adaptions\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GE(std::stoi(summary.substr(at + 18)), 1);
  EXPECT_EQ(summary.find("\"elements per cell\": [80]"), std::string::npos) << "not refined";

  run(*smallDeck(1, 0.0, false, tweak(0.2)), "split");
  const std::string first = read("split/summary.json");
  EXPECT_EQ(first.find("\"elements per cell\": [80]"), std::string::npos) << "not refined before the split";
  run(*smallDeck(1, 0.0, false, tweak(0.4)), "split", "split");
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
  EXPECT_EQ(read("split/snapshots.xdmf"), read("whole/snapshots.xdmf"));
}

class SceneWarmStartRun : public run::testing::SceneRunFixture {
protected:
  // Runs to 0.2 whole and split at 0.1 at lambda = 5 with the warm start and the given
  // 'Solver/Preconditioner'; the restarted run's table must be the uninterrupted one's.
  void expectRestartBitForBit(const std::string& preconditioner)
  {
    const auto settings = [preconditioner](double end) {
      return [preconditioner, end](Teuchos::ParameterList& d) {
        d.sublist("Flow").set("Viscosity ratio", 5.0);
        d.sublist("Solver").set("Warm start", true);
        d.sublist("Solver").set("Preconditioner", preconditioner);
        d.sublist("Time integration").set("End time", end);
      };
    };
    const auto deck = smallDeck(1, 1.6, true, settings(0.2));
    run(*deck, "whole");
    run(*smallDeck(1, 1.6, true, settings(0.1)), "split");
    // The checkpoint holds the next solve's start: the last 6 pairs (a step has 6 stages).
    const auto checkpoint = capsula::io::readCheckpoint((root_ / "split" / "checkpoint.h5").string());
    const auto rhs = checkpoint.arrays.find("scene.gmresWarmStart.rhs");
    const auto solutions = checkpoint.arrays.find("scene.gmresWarmStart.solutions");
    ASSERT_NE(rhs, checkpoint.arrays.end());
    ASSERT_NE(solutions, checkpoint.arrays.end());
    EXPECT_EQ(rhs->second.size(), 6 * checkpoint.arrays.at("timeint.state").size());
    EXPECT_EQ(solutions->second.size(), rhs->second.size());
    const auto result = run(*deck, "split", "split");
    EXPECT_EQ(result.status, "finished");
    // Bit for bit: the tables are the same text (a cold first solve after the restart moves
    // the positions by ~1e-10 and shows in the 17-digit columns).
    EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
  }
};

TEST_F(SceneWarmStartRun, RestartReproducesTheUninterruptedRunAtLambdaFive)
{
  expectRestartBitForBit("None");
}

// The cell blocks are rebuilt at each step's first solve and kept through its stages, so a
// run restarted at a step rebuilds them where the uninterrupted run did. Rebuilt at any
// other geometry, they steer flexible GMRES to another iterate within the tolerance, and
// the table's last digits differ.
TEST_F(SceneWarmStartRun, RestartWithCellBlocksReproducesTheUninterruptedRun)
{
  expectRestartBitForBit("Cell blocks");
}
