#include "SceneRunFixture.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/io/MetricsCsv.hpp>
#include <capsula/io/SnapshotFile.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/run/SceneRun.hpp>

#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace core = capsula::core;
namespace scene = capsula::scene;
namespace fs = std::filesystem;
using capsula::run::testing::smallDeck;

class SceneRunTest : public capsula::run::testing::SceneRunFixture {
protected:
  /// The snapshot series of two run directories hold the same values, bit for bit.
  void expectSameSnapshots(const std::string& a, const std::string& b) const
  {
    const std::string fileA = (root_ / a / "snapshots.h5").string(), fileB = (root_ / b / "snapshots.h5").string();
    const std::size_t count = capsula::io::readSnapshotLayouts(fileB).size();
    ASSERT_EQ(capsula::io::readSnapshotLayouts(fileA).size(), count);
    EXPECT_GT(count, 1u);
    for (std::size_t k = 0; k < count; ++k) {
      const auto x = capsula::io::readSnapshot(fileA, k), y = capsula::io::readSnapshot(fileB, k);
      EXPECT_EQ(x.time, y.time);
      ASSERT_EQ(x.blocks.size(), y.blocks.size());
      for (std::size_t i = 0; i < x.blocks.size(); ++i) {
        EXPECT_EQ(x.blocks[i].positions, y.blocks[i].positions) << "snapshot " << k;
        ASSERT_EQ(x.blocks[i].nodeFields.size(), y.blocks[i].nodeFields.size());
        for (std::size_t f = 0; f < x.blocks[i].nodeFields.size(); ++f) {
          EXPECT_EQ(x.blocks[i].nodeFields[f].values, y.blocks[i].nodeFields[f].values) << "snapshot " << k;
        }
      }
    }
    EXPECT_EQ(read(a + "/snapshots.xdmf"), read(b + "/snapshots.xdmf"));
  }
};

TEST_F(SceneRunTest, WritesTheOutputContract)
{
  const auto result = run(*smallDeck(1, 2.0, true), "out");
  EXPECT_EQ(result.status, "finished");
  EXPECT_DOUBLE_EQ(result.time, 0.2);
  for (const char* file :
       {"metrics.csv", "summary.json", "snapshots.xdmf", "snapshots.h5", "checkpoint.h5", "deck.xml", "run.json"}) {
    EXPECT_TRUE(fs::exists(root_ / "out" / file)) << file;
  }
  // One file holds every snapshot: t = 0, 0.1, 0.2.
  EXPECT_EQ(capsula::io::readSnapshotLayouts((root_ / "out" / "snapshots.h5").string()).size(), 3u);
  const auto table = capsula::io::readCsvTable((root_ / "out" / "metrics.csv").string());
  const std::vector<std::string> required{"time",         "step",
                                          "dt",           "D12",
                                          "D13",          "D23",
                                          "x_c",          "y_c",
                                          "z_c",          "u_slip",
                                          "u_migr",       "volume",
                                          "area",         "reduced_volume",
                                          "footprint_xz", "mean_shear_stress"};
  ASSERT_GE(table.columns.size(), required.size());
  for (std::size_t k = 0; k < required.size(); ++k) {
    EXPECT_EQ(table.columns[k], required[k]);
  }
  ASSERT_EQ(table.rows.size(), 3u); // t = 0, 0.1, 0.2
  EXPECT_DOUBLE_EQ(table.rows[2][0], 0.2);
  EXPECT_GT(table.rows[2][3], 0.01); // the capsule has deformed
  const std::string summary = read("out/summary.json");
  EXPECT_NE(summary.find("\"status\": \"finished\""), std::string::npos);
  EXPECT_NE(summary.find("kernel: Wall"), std::string::npos);
  EXPECT_NE(summary.find("\"deck\""), std::string::npos);
  EXPECT_NE(summary.find("\"git sha\""), std::string::npos);
}

TEST_F(SceneRunTest, WallShearStressCostsOnlyWhenAsked)
{
  const auto flowPoints = core::timer("Flow velocity at points");
  int before = flowPoints->numCalls();
  auto result = run(*smallDeck(1, 2.0, true), "off");
  EXPECT_EQ(flowPoints->numCalls(), before);
  for (const auto& term : result.terms) {
    EXPECT_EQ(term.find("wall shear stress"), std::string::npos) << term;
  }
  EXPECT_EQ(read("off/metrics.csv").find("wall_area_upstream"), std::string::npos);

  before = flowPoints->numCalls();
  result = run(*smallDeck(1, 2.0, true,
                          [](Teuchos::ParameterList& d) {
                            auto& wall = d.sublist("Output").sublist("Wall shear stress");
                            wall.set("Enabled", true);
                            wall.set("Spacing", 1.0);
                          }),
               "on");
  EXPECT_GT(flowPoints->numCalls(), before);
  EXPECT_NE(read("on/metrics.csv").find("wall_area_upstream"), std::string::npos);
  const auto table = capsula::io::readCsvTable((root_ / "on" / "metrics.csv").string());
  // Undisturbed shear puts stress 1 on the wall; a cell above it raises some and lowers
  // some: the grid sees both sides of 1.
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(table.columns.begin(), table.columns.end(), name) -
                                    table.columns.begin());
  };
  const std::size_t minimum = column("wall_stress_min"), maximum = column("wall_stress_max");
  ASSERT_LT(maximum, table.columns.size());
  EXPECT_LT(table.rows.back()[minimum], 1.0);
  EXPECT_GT(table.rows.back()[maximum], 1.0);
}

TEST_F(SceneRunTest, LiftVelocityIsWhatTheFixedHeightRemoves)
{
  // A deformed cell near the wall lifts off (thesis Fig 5.13). Free, u_lift is its
  // instantaneous migration velocity; held at a fixed height, the centroid does not rise
  // (u_migr ~ 0) but u_lift still reports the rise rate the constraint removed
  // (Fig 5.14), of the same sign and size as the free cell's at this early time.
  run(*smallDeck(1, 1.6, true), "free");
  run(*smallDeck(1, 1.6, true,
                 [](Teuchos::ParameterList& d) { d.sublist("Cells").sublist("Cell 0").set("Fixed height", true); }),
      "held");
  const auto free = capsula::io::readCsvTable((root_ / "free" / "metrics.csv").string());
  const auto held = capsula::io::readCsvTable((root_ / "held" / "metrics.csv").string());
  const auto at = [](const capsula::io::CsvTable& t, const char* name) {
    const auto k = static_cast<std::size_t>(std::find(t.columns.begin(), t.columns.end(), name) - t.columns.begin());
    EXPECT_LT(k, t.columns.size()) << name;
    return t.rows.back().at(k);
  };
  // Free: the same velocity field, so equal to round-off.
  EXPECT_EQ(at(free, "u_lift"), at(free, "u_migr"));
  EXPECT_GT(at(free, "u_lift"), 1e-4); // lifts off the wall (measured 6.6e-4 at t = 0.2, barely deformed)
  // Held: the constraint removes the mean rise rate exactly (to round-off of the volume
  // integral), and u_lift keeps it.
  EXPECT_LT(std::abs(at(held, "u_migr")), 1e-12);
  EXPECT_GT(at(held, "u_lift"), 0.5 * at(free, "u_lift"));
  EXPECT_LT(at(held, "u_lift"), 2.0 * at(free, "u_lift"));
}

TEST_F(SceneRunTest, RestartReproducesTheUninterruptedRun)
{
  const auto deck = smallDeck(1, 1.6, true);
  run(*deck, "whole");
  const auto half =
      smallDeck(1, 1.6, true, [](Teuchos::ParameterList& d) { d.sublist("Time integration").set("End time", 0.1); });
  run(*half, "split");
  const auto result = run(*deck, "split", "split");
  EXPECT_EQ(result.status, "finished");
  // Bit for bit: the tables are the same text.
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
  // The restarted run appended to the same snapshot file: the same series, bit for bit.
  expectSameSnapshots("split", "whole");
  // Restarting into another directory carries the table and the snapshots over. (The
  // finished run in "split" has nothing left to do: a restart from it is refused.)
  run(*half, "half");
  run(*deck, "moved", "half");
  EXPECT_EQ(read("moved/metrics.csv"), read("whole/metrics.csv"));
  expectSameSnapshots("moved", "whole");
}

TEST_F(SceneRunTest, RestartRefusesAChangedDeck)
{
  run(*smallDeck(1, 1.6, true, [](Teuchos::ParameterList& d) { d.sublist("Time integration").set("End time", 0.1); }),
      "first");
  const auto changed =
      smallDeck(1, 1.6, true, [](Teuchos::ParameterList& d) { d.sublist("Flow").set("Capillary number", 0.6); });
  try {
    run(*changed, "first", "first");
    FAIL() << "a restart with another capillary number must be refused";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Flow/Capillary number'"), std::string::npos) << e.what();
  }
  try {
    run(*changed, "first", "nowhere");
    FAIL() << "a restart from a directory without a checkpoint must be refused";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--restart"), std::string::npos) << e.what();
  }
}

TEST_F(SceneRunTest, RejectsAnUnusableOutputDirectory)
{
  std::ofstream(root_ / "plain-file") << "not a directory\n";
  try {
    run(*smallDeck(0, 2.0, true), "plain-file/out");
    FAIL() << "a directory inside a file cannot be created";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("The output directory"), std::string::npos) << e.what();
  }
}

} // namespace
