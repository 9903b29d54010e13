// A scene run with receptor-ligand bonds: the adhesion columns of metrics.csv (and none
// without adhesion), the bonds in the snapshots, the rolling statistics in summary.json,
// and a restart that repeats the uninterrupted run bit for bit, the bond states carried by
// the checkpoint. Level-1
// sphere 0.03 a above a ligand wall, a few steps to t = 0.2.
#include "SceneRunFixture.hpp"

#include <capsula/io/MetricsCsv.hpp>
#include <capsula/io/SnapshotFile.hpp>
#include <capsula/run/MetricsTable.hpp>
#include <capsula/run/RollingStatistics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace io = capsula::io;
using capsula::run::testing::smallDeck;

class AdhesionRunTest : public capsula::run::testing::SceneRunFixture {};

// Stochastic bonds that form and break within a few steps (k_on0 n_L = 100 k, k_off0 =
// 5 k, k_B T = 1e-2 G a^2), the contact repulsion keeping the membrane off the wall.
// `patchRadius` > 0 spreads the receptors over patches and takes the virtual-work contact load.
Teuchos::RCP<Teuchos::ParameterList> adhesionDeck(double end, bool adhesion = true, double patchRadius = 0.0)
{
  return smallDeck(1, 1.03, true, [&](Teuchos::ParameterList& d) {
    d.sublist("Time integration").set("End time", end);
    d.sublist("Contact").set("Enabled", true);
    if (patchRadius > 0.0) {
      d.sublist("Contact").set("Load", std::string("Virtual work"));
      d.sublist("Adhesion").set("Patch radius", patchRadius);
    }
    auto& a = d.sublist("Adhesion");
    a.set("Enabled", adhesion);
    a.set("On-rate", 1.0);
    a.set("Off-rate", 5.0);
    a.set("Thermal energy", 1e-2);
    a.set("Seed", 7);
  });
}

std::size_t columnIndex(const io::CsvTable& table, const std::string& name)
{
  const auto it = std::find(table.columns.begin(), table.columns.end(), name);
  return static_cast<std::size_t>(it - table.columns.begin());
}

// The last snapshot's block `name` of a run directory, or null.
std::optional<io::SnapshotBlock> lastBlock(const std::string& file, const std::string& name)
{
  const std::size_t count = io::readSnapshotLayouts(file).size();
  for (auto& block : io::readSnapshot(file, count - 1).blocks) {
    if (block.name == name) {
      return block;
    }
  }
  return std::nullopt;
}

TEST_F(AdhesionRunTest, WritesTheAdhesionColumnsAndStatistics)
{
  run(*adhesionDeck(0.2), "bonds");
  const auto table = io::readCsvTable((root_ / "bonds" / "metrics.csv").string());
  const std::vector<std::string> last{"bonds", "bond_force", "bond_force_x", "bond_force_y", "contact_area", "min_gap"};
  ASSERT_GE(table.columns.size(), last.size());
  EXPECT_TRUE(std::equal(last.begin(), last.end(), table.columns.end() - static_cast<std::ptrdiff_t>(last.size())));
  ASSERT_EQ(table.rows.size(), 3u); // t = 0, 0.1, 0.2
  const auto at = [&](std::size_t row, const std::string& name) { return table.rows[row][columnIndex(table, name)]; };
  EXPECT_EQ(at(0, "bonds"), 0.0); // the first bonds form after the first step
  EXPECT_GT(at(2, "bonds"), 0.0);
  EXPECT_GT(at(2, "bond_force"), 0.0);
  EXPECT_GT(at(2, "contact_area"), 0.0);
  EXPECT_GT(at(2, "min_gap"), 0.0);
  EXPECT_LT(at(2, "min_gap"), 0.05);
  // The snapshot at t = 0.2 holds each bond as a segment receptor - ligand with its force:
  // as many as metrics.csv counts, their forces summing to its total in the same order
  // (1e-12 of the total for round-off).
  const auto bonds = lastBlock((root_ / "bonds" / "snapshots.h5").string(), "bonds0");
  ASSERT_TRUE(bonds.has_value());
  EXPECT_EQ(static_cast<double>(bonds->cellCount()), at(2, "bonds"));
  double fx = 0.0, fy = 0.0;
  for (std::size_t k = 0; k < bonds->cellCount(); ++k) {
    fx += bonds->cellFields[0].values[3 * k];
    fy += bonds->cellFields[0].values[3 * k + 1];
    EXPECT_EQ(bonds->positions[6 * k + 4], 0.0); // the ligand end lies on the wall
  }
  EXPECT_NEAR(fx, at(2, "bond_force_x"), 1e-12 * at(2, "bond_force"));
  EXPECT_NEAR(fy, at(2, "bond_force_y"), 1e-12 * at(2, "bond_force"));
  const std::string summary = read("bonds/summary.json");
  for (const char* key : {"\"adhesion\"", "\"mean velocity along the flow\"", "\"pause fraction\"",
                          "\"pause threshold (velocity)\"", "\"bonds\"", "adhesion: Slip (Bell) bonds"}) {
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  }

  run(*adhesionDeck(0.2, false), "free");
  const auto free = io::readCsvTable((root_ / "free" / "metrics.csv").string());
  EXPECT_EQ(std::count(free.columns.begin(), free.columns.end(), "bonds"), 0);
  EXPECT_EQ(read("free/summary.json").find("pause fraction"), std::string::npos);
}

TEST_F(AdhesionRunTest, RestartReproducesTheUninterruptedRun)
{
  run(*adhesionDeck(0.2), "whole");
  run(*adhesionDeck(0.1), "split");
  const auto result = run(*adhesionDeck(0.2), "split", "split");
  EXPECT_EQ(result.status, "finished");
  const std::string whole = read("whole/metrics.csv");
  EXPECT_EQ(read("split/metrics.csv"), whole); // bit for bit: the same text
  const auto a = lastBlock((root_ / "whole" / "snapshots.h5").string(), "bonds0");
  const auto b = lastBlock((root_ / "split" / "snapshots.h5").string(), "bonds0");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->positions, b->positions);
  EXPECT_EQ(a->cellFields[0].values, b->cellFields[0].values);
  // Not a vacuous comparison: bonds formed (and broke) between the outputs.
  const auto table = io::readCsvTable((root_ / "whole" / "metrics.csv").string());
  EXPECT_GT(table.rows.back()[columnIndex(table, "bonds")], 0.0);
}

// The same with receptors on patches of 0.3 a (rebuilt from the unstressed shape on restart)
// and the virtual-work contact load. A patch's mean lies inside the curved membrane, by about
// rho^2 / 8 = 0.011 a here (test_bond_forces.cpp), so its receptor binds from a little higher
// up: the reaction distance is measured from that mean.
TEST_F(AdhesionRunTest, RestartWithPatchesReproducesTheUninterruptedRun)
{
  run(*adhesionDeck(0.2, true, 0.3), "whole");
  run(*adhesionDeck(0.1, true, 0.3), "split");
  const auto result = run(*adhesionDeck(0.2, true, 0.3), "split", "split");
  EXPECT_EQ(result.status, "finished");
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv")); // bit for bit
  const auto table = io::readCsvTable((root_ / "whole" / "metrics.csv").string());
  double most = 0.0;
  for (const auto& row : table.rows) {
    most = std::max(most, row[columnIndex(table, "bonds")]);
  }
  EXPECT_GT(most, 0.0); // bonds did form
}

TEST(AdhesionMetrics, ColumnsPerCellComeLastInTheOrderOfTheRow)
{
  namespace run = capsula::run;
  const auto columns = run::metricsColumns(false, 2, false, true);
  const std::vector<std::string> last{"bonds_0",        "bonds_1",        "bond_force_0",   "bond_force_1",
                                      "bond_force_x_0", "bond_force_x_1", "bond_force_y_0", "bond_force_y_1",
                                      "contact_area_0", "contact_area_1", "min_gap_0",      "min_gap_1"};
  ASSERT_GE(columns.size(), last.size());
  EXPECT_TRUE(std::equal(last.begin(), last.end(), columns.end() - static_cast<std::ptrdiff_t>(last.size())));
  EXPECT_EQ(run::metricsColumns(false, 2, false, false).size(), columns.size() - last.size());
  std::vector<run::CellSample> samples(2);
  for (int c = 0; c < 2; ++c) {
    capsula::adhesion::AdhesionSummary a;
    a.bonds = 10.0 + c;
    a.bondForce = capsula::mesh::Vec3(-3.0 - c, -4.0, 0.0); // |F| = 5, sqrt(32): sums of exact squares
    a.contactArea = 0.5 + c;
    a.minimumGap = 0.02 + c;
    samples[static_cast<std::size_t>(c)].adhesion = a;
  }
  const auto row = run::metricsRow(1.0, 3, 0.1, samples, {}, {});
  const std::vector<double> tail(row.end() - 12, row.end());
  const std::vector<double> expected{10.0, 11.0, 5.0, std::sqrt(32.0), -3.0, -4.0, -4.0, -4.0, 0.5, 1.5, 0.02, 1.02};
  EXPECT_EQ(tail, expected);
}

TEST(AdhesionMetrics, PausesAreTheIntervalsSlowerThanTheThreshold)
{
  // x = 0, 1, 1.005, 1.006, 2 at t = 0..4: interval velocities 1, 0.005, 0.001, 0.994, so
  // at the threshold 0.01 two intervals in one run are paused.
  const std::vector<double> times{0.0, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> centroids{0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.005, 1.0, 0.0, 1.006, 1.0, 0.0, 2.0, 1.0, 0.0};
  const auto s = capsula::run::rollingStatistics(times, centroids, 0.01);
  EXPECT_EQ(s.observedTime, 4.0);
  EXPECT_EQ(s.meanVelocity, 0.5);
  EXPECT_EQ(s.pauseFraction, 0.5);
  EXPECT_EQ(s.pauses, 1);
  EXPECT_EQ(s.longestPause, 2.0);
  // One output: nothing observed yet.
  EXPECT_EQ(capsula::run::rollingStatistics({0.0}, {0.0, 1.0, 0.0}, 0.01).observedTime, 0.0);
}

} // namespace
