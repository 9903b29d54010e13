// Runs under a time-dependent shear rate ('Flow/Shear rate', operators/ShearRate.hpp): cell3d
// and tether2d with amplitude 0 are the steady runs bit for bit; a cell in unbounded shear
// is carried with k(t) y_c; the wall shear stress map follows k at the output; a cell3d
// restart in the middle of a period is the uninterrupted run bit for bit (tether2d's:
// test_tether_run.cpp).
#include "SceneRunFixture.hpp"
#include "Tether2DRunTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/io/MetricsCsv.hpp>
#include <capsula/scene2d/TetherRun2D.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace {

using capsula::run::testing::smallDeck;

class PulsatileRunTest : public capsula::run::testing::SceneRunFixture {};

// Pulsatile shear with `amplitude` and `period` in a deck.
void setPulsatile(Teuchos::ParameterList& deck, double amplitude, double period)
{
  auto& rate = deck.sublist("Flow").sublist("Shear rate");
  rate.set("Form", std::string("Pulsatile"));
  rate.set("Amplitude", amplitude);
  rate.set("Period", period);
}

// Column `name` of a metrics table.
std::vector<double> pulsatileColumn(const capsula::io::CsvTable& table, const std::string& name)
{
  const auto k =
      static_cast<std::size_t>(std::find(table.columns.begin(), table.columns.end(), name) - table.columns.begin());
  EXPECT_LT(k, table.columns.size()) << name;
  std::vector<double> values;
  for (const auto& row : table.rows) {
    values.push_back(row.at(k));
  }
  return values;
}

// The integral of k = 1 + A sin(2 pi s / T) over [0, t]: the distance a point at height 1
// travels.
double shearDisplacement(double amplitude, double period, double t)
{
  return t + amplitude * period / (2.0 * M_PI) * (1.0 - std::cos(2.0 * M_PI * t / period));
}

TEST_F(PulsatileRunTest, AmplitudeZeroIsTheSteadyRunBitForBit)
{
  // Ca 0.3, level 1, near the wall. The same largest step in both runs (the pulsatile run
  // limits it to Period / 20 = 0.05): only the flow differs, by a factor 1 + 0 sin(...).
  const auto steady = smallDeck(
      1, 1.6, true, [](Teuchos::ParameterList& d) { d.sublist("Time integration").set("Maximum step", 0.05); });
  const auto flat = smallDeck(1, 1.6, true, [](Teuchos::ParameterList& d) {
    d.sublist("Time integration").set("Maximum step", 0.05);
    setPulsatile(d, 0.0, 1.0);
  });
  const auto pulsing = smallDeck(1, 1.6, true, [](Teuchos::ParameterList& d) {
    d.sublist("Time integration").set("Maximum step", 0.05);
    setPulsatile(d, 0.5, 1.0);
  });
  run(*steady, "steady");
  run(*flat, "flat");
  run(*pulsing, "pulsing");
  EXPECT_EQ(read("flat/metrics.csv"), read("steady/metrics.csv"));
  EXPECT_NE(read("pulsing/metrics.csv"), read("steady/metrics.csv"));
}

TEST_F(PulsatileRunTest, CentroidIsCarriedWithTheShearRateOfTheInstant)
{
  // A sphere in unbounded shear (no wall) deforms point-symmetrically about its centroid,
  // which moves with the undisturbed flow there: dx_c/dt = k(t) y_c, y_c fixed. Over one
  // period T = 0.4 with A = 0.5 the centroid at y_c = 2 travels 2 (t + A T / 2 pi (1 - cos)),
  // at T/2 0.527 against the 0.4 of steady shear and 0.273 with the sine's sign flipped.
  const double amplitude = 0.5, period = 0.4;
  const auto deck = smallDeck(1, 2.0, false, [&](Teuchos::ParameterList& d) {
    setPulsatile(d, amplitude, period);
    d.sublist("Time integration").set("End time", period);
    d.sublist("Output").set("Interval", period / 8.0);
  });
  run(*deck, "free");
  const auto table = capsula::io::readCsvTable((root_ / "free" / "metrics.csv").string());
  const auto t = pulsatileColumn(table, "time"), x = pulsatileColumn(table, "x_c"), y = pulsatileColumn(table, "y_c"),
             slip = pulsatileColumn(table, "u_slip");
  ASSERT_EQ(t.size(), 9u);
  double worstX = 0.0, worstSlip = 0.0, worstY = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    worstX = std::max(worstX, std::abs(x[k] - x[0] - y[0] * shearDisplacement(amplitude, period, t[k])));
    worstY = std::max(worstY, std::abs(y[k] - y[0]));
    worstSlip = std::max(worstSlip, std::abs(slip[k]));
  }
  std::printf("  largest |x_c - x_c(0) - y_c int k dt| = %.3g, |y_c - y_c(0)| = %.3g, |u_slip| = %.3g\n", worstX,
              worstY, worstSlip);
  // The level-1 icosahedron is point-symmetric: what is left is the integrator's error
  // (RKF45 at tolerance 1e-4) and round-off, far below the 0.13 a wrong sign would leave.
  EXPECT_LT(worstX, 1e-3);
  EXPECT_LT(worstY, 1e-6);
  // u_slip = k(t) y_c - dx_c/dt at the output instant: 0 here; with k = 1 in place of
  // k(T/4) = 1.5 it would read 1 at T/4.
  EXPECT_LT(worstSlip, 1e-3);
}

TEST_F(PulsatileRunTest, WallShearStressFollowsTheShearRateOfTheOutput)
{
  // A sphere high above the wall (centre at 4 radii) disturbs the wall stress little: the
  // map's extremes bracket the ambient k(t) at every output, 1, 1.5, 1, 0.5, 1 over the
  // period 0.4 (a map computed with k = 1 would stay near 1 at T/4 and 3T/4).
  const auto deck = smallDeck(1, 4.0, true, [](Teuchos::ParameterList& d) {
    setPulsatile(d, 0.5, 0.4);
    d.sublist("Time integration").set("End time", 0.4);
    auto& wall = d.sublist("Output").sublist("Wall shear stress");
    wall.set("Enabled", true);
    wall.set("Spacing", 1.0);
  });
  run(*deck, "wall");
  const auto table = capsula::io::readCsvTable((root_ / "wall" / "metrics.csv").string());
  const auto t = pulsatileColumn(table, "time"), low = pulsatileColumn(table, "wall_stress_min"),
             high = pulsatileColumn(table, "wall_stress_max");
  ASSERT_EQ(t.size(), 5u);
  double worst = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double ambient = 1.0 + 0.5 * std::sin(2.0 * M_PI * t[k] / 0.4);
    std::printf("  t = %.2f: k = %.3f, wall stress from %.4f to %.4f\n", t[k], ambient, low[k], high[k]);
    EXPECT_LE(low[k], ambient + 1e-12); // at t = 0 the unstressed sphere leaves the wall at k
    EXPECT_GE(high[k], ambient - 1e-12);
    worst = std::max({worst, ambient - low[k], high[k] - ambient});
  }
  // The disturbance of the cell 4 radii up: measured at most 0.029 (at t = 0.4); k = 1 in
  // place of k(t) would miss by 0.5 at T/4 and 3T/4.
  EXPECT_LT(worst, 0.1);
}

TEST_F(PulsatileRunTest, RestartMidPeriodReproducesTheUninterruptedRun)
{
  // Period 0.4, outputs every 0.1: the first part stops at t = 0.1, a quarter period in,
  // where the shear rate is at its largest.
  const auto deck = smallDeck(1, 1.6, true, [](Teuchos::ParameterList& d) { setPulsatile(d, 0.5, 0.4); });
  run(*deck, "whole");
  const auto half = smallDeck(1, 1.6, true, [](Teuchos::ParameterList& d) {
    setPulsatile(d, 0.5, 0.4);
    d.sublist("Time integration").set("End time", 0.1);
  });
  run(*half, "split");
  const auto result = run(*deck, "split", "split");
  EXPECT_EQ(result.status, "finished");
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
}

TEST_F(PulsatileRunTest, TabulatedRunRestartsBitForBitAndOnlyWithItsWaveform)
{
  // A pulse of period 0.2 (outputs every 0.1: two per period); the restart at t = 0.1 is at
  // the pulse's peak.
  const std::string file = (root_ / "pulse.dat").string();
  std::ofstream(file) << "# time, shear rate\n0 1\n0.1 2\n0.2 1\n";
  const auto deckTo = [&file](double end) {
    return smallDeck(1, 1.6, true, [&](Teuchos::ParameterList& d) {
      auto& rate = d.sublist("Flow").sublist("Shear rate");
      rate.set("Form", std::string("Tabulated"));
      rate.set("Waveform file", file);
      d.sublist("Time integration").set("End time", end);
    });
  };
  run(*deckTo(0.2), "whole");
  run(*deckTo(0.1), "split");
  run(*deckTo(0.2), "split", "split");
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
  EXPECT_NE(read("whole/summary.json").find("tabulated waveform of 3 samples"), std::string::npos);

  run(*deckTo(0.1), "again");
  std::ofstream(file) << "0 1\n0.1 3\n0.2 1\n"; // the file changed since
  try {
    run(*deckTo(0.2), "again", "again");
    ADD_FAILURE() << "a restart with another waveform ran";
  } catch (const capsula::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("another waveform than 'Flow/Shear rate/Waveform file'"), std::string::npos)
        << e.what();
  }
}

// tether2d: a free cell without the wall (no tether), 32 points, Ca 0.1, lambda 1 (tau = t).
capsula::scene2d::TetherRunResult2D runFreeCell2D(const std::vector<std::string>& extra, const std::string& directory)
{
  std::vector<std::string> settings{"Wall/Enabled=false",         "Tether/Enabled=false",
                                    "Cell/Lowest point height=1", "Cell/Number of points=32",
                                    "Flow/Capillary number=0.1",  "Time integration/Maximum step=0.1",
                                    "Output/Checkpoint every=0"};
  settings.insert(settings.end(), extra.begin(), extra.end());
  capsula::scene2d::TetherRun2D run(Teuchos::rcp(new Teuchos::SerialComm<int>),
                                    capsula::scene2d::testing::tether2dDeck(settings), nullptr);
  return run.run(directory, std::nullopt);
}

TEST_F(PulsatileRunTest, Tether2DCellIsCarriedWithTheShearRateOfTheInstant)
{
  const double amplitude = 0.5, period = 2.0;
  const std::vector<std::string> pulsatile{"Flow/Shear rate/Form=Pulsatile", "Flow/Shear rate/Amplitude=0.5",
                                           "Flow/Shear rate/Period=2"};
  auto extra = pulsatile;
  extra.insert(extra.end(), {"Time integration/End time=2", "Output/Interval=0.25"});
  runFreeCell2D(extra, (root_ / "pulsing").string());
  const auto table = capsula::io::readCsvTable((root_ / "pulsing" / "metrics.csv").string());
  const auto t = pulsatileColumn(table, "time"), x = pulsatileColumn(table, "centroid_x"),
             y = pulsatileColumn(table, "centroid_y");
  ASSERT_EQ(t.size(), 9u);
  double worstX = 0.0, worstY = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    worstX = std::max(worstX, std::abs(x[k] - x[0] - y[0] * shearDisplacement(amplitude, period, t[k])));
    worstY = std::max(worstY, std::abs(y[k] - y[0]));
  }
  std::printf("  2D: largest |x_c - x_c(0) - y_c int k dt| = %.3g (y_c = %.4g), |y_c - y_c(0)| = %.3g\n", worstX, y[0],
              worstY);
  // The displacement at T/2 is y_c (1 + 2 A / pi) = 1.32 y_c, at T/4 y_c (0.5 + A / pi); a
  // wrong sign or a steady flow misses by 0.3 y_c or more.
  EXPECT_LT(worstX, 1e-3 * y[0]);
  EXPECT_LT(worstY, 1e-6);

  // Amplitude 0 is the steady run bit for bit (the same largest step, 0.1 = Period / 20).
  runFreeCell2D({"Time integration/End time=1", "Output/Interval=0.25"}, (root_ / "steady").string());
  runFreeCell2D({"Flow/Shear rate/Form=Pulsatile", "Flow/Shear rate/Amplitude=0", "Flow/Shear rate/Period=2",
                 "Time integration/End time=1", "Output/Interval=0.25"},
                (root_ / "flat").string());
  EXPECT_EQ(read("flat/metrics.csv"), read("steady/metrics.csv"));
}

} // namespace
