// A scene run with receptor-ligand bonds: the adhesion columns of metrics.csv (and none
// without adhesion), the rolling statistics in summary.json, and a restart that repeats
// the uninterrupted run bit for bit, the bond states carried by the checkpoint. Level-1
// sphere 0.03 a above a ligand wall, a few steps to t = 0.2.
#include "SceneRunFixture.hpp"

#include <capsula/io/MetricsCsv.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

namespace io = capsula::io;
using capsula::run::testing::smallDeck;

class AdhesionRunTest : public capsula::run::testing::SceneRunFixture {};

// Stochastic bonds that form and break within a few steps (k_on0 n_L = 100 k, k_off0 =
// 5 k, k_B T = 1e-2 G a^2), the contact repulsion keeping the membrane off the wall.
Teuchos::RCP<Teuchos::ParameterList> adhesionDeck(double end, bool adhesion = true)
{
  return smallDeck(1, 1.03, true, [&](Teuchos::ParameterList& d) {
    d.sublist("Time integration").set("End time", end);
    d.sublist("Contact").set("Enabled", true);
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
  // Not a vacuous comparison: bonds formed (and broke) between the outputs.
  const auto table = io::readCsvTable((root_ / "whole" / "metrics.csv").string());
  EXPECT_GT(table.rows.back()[columnIndex(table, "bonds")], 0.0);
}

} // namespace
