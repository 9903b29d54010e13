// A scene run with a tether: the tether columns of metrics.csv (and none without it), the
// tether segment in the snapshots, its peak in summary.json, and a restart that repeats the
// uninterrupted run bit for bit. A level-1 sphere released 0.05 a above the wall, tethered
// at its lowest point with the default anchor below it and an unstressed start, in shear to
// t = 0.2.
#include "SceneRunFixture.hpp"

#include <capsula/io/MetricsCsv.hpp>
#include <capsula/io/SnapshotFile.hpp>
#include <capsula/run/MetricsTable.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

namespace io = capsula::io;
using capsula::run::testing::smallDeck;

class TetherRun3DTest : public capsula::run::testing::SceneRunFixture {};

Teuchos::RCP<Teuchos::ParameterList> tetheredDeck(double end, bool tether = true)
{
  return smallDeck(1, 1.05, true, [&](Teuchos::ParameterList& d) {
    d.sublist("Time integration").set("End time", end);
    d.sublist("Flow").set("Capillary number", 0.1);
    d.sublist("Tether").set("Enabled", tether);
    d.sublist("Tether").set("Spring constant", 20.0);
  });
}

std::size_t tetherColumn(const io::CsvTable& table, const std::string& name)
{
  const auto it = std::find(table.columns.begin(), table.columns.end(), name);
  EXPECT_NE(it, table.columns.end()) << name;
  return static_cast<std::size_t>(it - table.columns.begin());
}

TEST_F(TetherRun3DTest, WritesTheTetherColumnsSnapshotAndSummary)
{
  run(*tetheredDeck(0.2), "tethered");
  const auto table = io::readCsvTable((root_ / "tethered" / "metrics.csv").string());
  const std::vector<std::string> last{"tether_force",  "tether_force_x",   "tether_force_y", "tether_force_z",
                                      "tether_length", "tether_angle_deg", "pivot_angle_deg"};
  ASSERT_GE(table.columns.size(), last.size());
  EXPECT_TRUE(std::equal(last.begin(), last.end(), table.columns.end() - static_cast<std::ptrdiff_t>(last.size())));
  ASSERT_EQ(table.rows.size(), 3u); // t = 0, 0.1, 0.2
  const auto at = [&](std::size_t row, const std::string& name) { return table.rows[row][tetherColumn(table, name)]; };
  EXPECT_EQ(at(0, "tether_force"), 0.0); // unstressed at the start
  EXPECT_NEAR(at(0, "tether_angle_deg"), 90.0, 1e-12);
  // The flow carries the cell downstream: the tether stretches, leans downstream and pulls
  // the membrane back upstream and down; the centroid passes the anchor.
  EXPECT_GT(at(2, "tether_force"), at(1, "tether_force"));
  EXPECT_GT(at(2, "tether_force"), 0.0);
  EXPECT_LT(at(2, "tether_force_x"), 0.0);
  EXPECT_LT(at(2, "tether_force_y"), 0.0);
  EXPECT_LT(std::abs(at(2, "tether_force_z")), 1e-9 * at(2, "tether_force")); // z -> -z symmetry
  EXPECT_LT(at(2, "tether_angle_deg"), 90.0);
  EXPECT_LT(at(2, "pivot_angle_deg"), at(0, "pivot_angle_deg"));
  EXPECT_NEAR(at(0, "pivot_angle_deg"), 90.0, 1e-6); // the centroid straight above the anchor

  // The last snapshot's tether block: one segment from the attachment to the anchor on the
  // wall, with the force of the metrics row.
  const std::string file = (root_ / "tethered" / "snapshots.h5").string();
  const std::size_t count = io::readSnapshotLayouts(file).size();
  bool found = false;
  for (const auto& block : io::readSnapshot(file, count - 1).blocks) {
    if (block.name != "tether") {
      continue;
    }
    found = true;
    ASSERT_EQ(block.positions.size(), 6u);
    EXPECT_EQ(block.positions[4], 0.0); // the anchor lies on the wall
    EXPECT_EQ(block.cellFields[0].name, "force");
    // The last snapshot is at t = 0.2; the table holds the same number as text (1e-12: its digits).
    EXPECT_NEAR(block.cellFields[0].values[0], at(2, "tether_force_x"), 1e-12 * at(2, "tether_force"));
  }
  EXPECT_TRUE(found);

  // summary.json: the peak over every step is at least the largest output value (the force
  // still grows at t = 0.2, so the peak is the last step's, the last output's), and in units of
  // mu k a^2 it is the peak over Ca = 0.1.
  const std::string summary = read("tethered/summary.json");
  for (const char* key : {"\"tether\"", "\"peak force\"", "\"peak force / Ca\"", "\"time of peak force\"",
                          "\"final force change rate\"", "\"pivot angle (degrees)\"", "tether: Cells/Cell 0 held at"}) {
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  }
  const auto number = [&](const std::string& key) {
    const auto where = summary.find("\"" + key + "\": ");
    return where == std::string::npos ? -1.0 : std::stod(summary.substr(where + key.size() + 4));
  };
  // The table holds the force as text of 17 digits: 1e-12 relative.
  EXPECT_NEAR(number("peak force"), at(2, "tether_force"), 1e-12 * at(2, "tether_force"));
  EXPECT_NEAR(number("peak force / Ca"), number("peak force") / 0.1, 1e-12 * number("peak force / Ca"));
  EXPECT_NEAR(number("time of peak force"), 0.2, 1e-12);

  run(*tetheredDeck(0.2, false), "free");
  const auto free = io::readCsvTable((root_ / "free" / "metrics.csv").string());
  EXPECT_EQ(std::count(free.columns.begin(), free.columns.end(), "tether_force"), 0);
  EXPECT_EQ(read("free/summary.json").find("\"tether\""), std::string::npos);
}

TEST_F(TetherRun3DTest, RestartReproducesTheUninterruptedRun)
{
  // The tether is rebuilt from the deck and the initial shape; its record (the peak) comes
  // from the checkpoint: the rows and the peak are the uninterrupted run's, bit for bit.
  run(*tetheredDeck(0.2), "whole");
  run(*tetheredDeck(0.1), "split");
  const auto result = run(*tetheredDeck(0.2), "split", "split");
  EXPECT_EQ(result.status, "finished");
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
  const auto peak = [&](const std::string& directory) {
    const std::string summary = read(directory + "/summary.json");
    const auto at = summary.find("\"peak force\"");
    return summary.substr(at, summary.find(',', at) - at);
  };
  EXPECT_EQ(peak("split"), peak("whole"));
  const auto table = io::readCsvTable((root_ / "whole" / "metrics.csv").string());
  EXPECT_GT(table.rows.back()[tetherColumn(table, "tether_force")], 0.0); // not a vacuous comparison
}

TEST(TetherMetrics, ColumnsComeLastOnceInTheOrderOfTheRow)
{
  namespace run = capsula::run;
  const auto columns = run::metricsColumns(false, 2, false, true, true);
  const std::vector<std::string> last{"tether_force",  "tether_force_x",   "tether_force_y", "tether_force_z",
                                      "tether_length", "tether_angle_deg", "pivot_angle_deg"};
  EXPECT_TRUE(std::equal(last.begin(), last.end(), columns.end() - static_cast<std::ptrdiff_t>(last.size())));
  EXPECT_EQ(run::metricsColumns(false, 2, false, true, false).size(), columns.size() - last.size());
  // Two cells with adhesion, the second tethered: its values after both cells' adhesion columns.
  std::vector<run::CellSample> samples(2);
  for (auto& s : samples) {
    s.adhesion = capsula::adhesion::AdhesionSummary{};
  }
  run::TetherSample t;
  t.state.force = capsula::mesh::Vec3(-3.0, -4.0, 0.5); // |F| = sqrt(25.25)
  t.state.length = 0.08;
  t.state.inclinationDegrees = 53.0;
  t.pivotAngleDegrees = 25.0;
  samples[1].tether = t;
  const auto row = run::metricsRow(1.0, 3, 0.1, samples, {}, {});
  const std::vector<double> tail(row.end() - 7, row.end());
  const std::vector<double> expected{std::sqrt(25.25), -3.0, -4.0, 0.5, 0.08, 53.0, 25.0};
  EXPECT_EQ(tail, expected);
}

} // namespace
