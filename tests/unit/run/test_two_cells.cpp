// Two cells in one scene (thesis Chapter 6): the per-cell and pair columns of metrics.csv,
// the symmetries of the side-by-side and mirrored configurations, the far-separation limit
// against the single cell, and the stop when two surfaces come too close. Level-1 meshes,
// RK4 steps of fixed size, a handful of steps: each run takes about a second.
#include "SceneRunFixture.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/io/MetricsCsv.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/run/SceneRun.hpp>

#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace core = capsula::core;
namespace io = capsula::io;
namespace scene = capsula::scene;
namespace fs = std::filesystem;
using scene::testing::realArray;

using Point = std::array<double, 3>;

// Mirror symmetry (z -> -z) of the discretisation, with the default quadrature. The mesh
// is mirror-symmetric, and the singular quadrature of the single layer is built so that it
// does not depend on which local number the collocation node has (PolarRules.cpp,
// PolarRules.VertexRulesDoNotDependOnTheVertexNumbering): a mirrored element lists its
// vertices in the other order. Before that fix the single layer was mirror-symmetric only
// to 2e-5 relative at N_GL = 6. What remains is round-off of sums taken in another order:
// bound 1e-10 (the acceptance). A sign error or mixed-up cells give O(1).
constexpr int kSymmetricSingularPoints = 6; // the default N_GL
constexpr double kSymmetryTolerance = 1e-10;

// Two level-1 Skalak cells (C = 2.5, Ca = 0.3, lambda = 1, free) above the wall, RK4 steps
// of 0.02 to t = 0.1 (the regression runs show level 1 stable at 0.01-0.02), adaptive
// near-singular integration on (the cells are close).
Teuchos::RCP<Teuchos::ParameterList> pairDeck(const Point& a, const Point& b, int cells = 2)
{
  return capsula::run::testing::smallDeck(1, a[1], true, [&](Teuchos::ParameterList& d) {
    d.sublist("Cells").sublist("Cell 0").set("Center", realArray({a[0], a[1], a[2]}));
    if (cells == 2) {
      auto& second = d.sublist("Cells").sublist("Cell 1");
      second.set("Center", realArray({b[0], b[1], b[2]}));
      second.set("Mesh level", 1);
    }
    d.sublist("Discretisation").set("Near-singular distance", 1.0);
    auto& time = d.sublist("Time integration");
    time.set("Method", std::string("RK4"));
    time.set("Initial step", 0.02);
    time.set("End time", 0.1);
    d.sublist("Output").set("Interval", 0.05);
    d.sublist("Output").set("Snapshots", false);
  });
}

class TwoCellsTest : public capsula::run::testing::SceneRunFixture {
protected:
  io::CsvTable table(const std::string& directory) const
  {
    return io::readCsvTable((root_ / directory / "metrics.csv").string());
  }
};

double value(const io::CsvTable& t, std::size_t row, const std::string& column)
{
  const auto it = std::find(t.columns.begin(), t.columns.end(), column);
  if (it == t.columns.end()) {
    ADD_FAILURE() << "no column " << column;
    return NAN;
  }
  return t.rows[row][static_cast<std::size_t>(it - t.columns.begin())];
}

// |a - sign b| relative to the larger of |a|, |b| and `scale` (a typical size of the
// quantity, so values that are zero by symmetry compare at an absolute level).
double mismatch(double a, double b, double sign, double scale)
{
  return std::abs(a - sign * b) / std::max({std::abs(a), std::abs(b), scale});
}

// The metrics compared between cells, with the sign a mirror z -> -z gives them and their
// typical size in these runs (the scale of the relative comparison).
struct Mirrored {
  const char* name;
  double sign;
  double scale;
};
constexpr std::array<Mirrored, 12> kMirrored{{{"x_c", 1, 1},
                                              {"y_c", 1, 1},
                                              {"z_c", -1, 1},
                                              {"u_slip", 1, 1e-2},
                                              {"u_migr", 1, 1e-3},
                                              {"w_c", -1, 1e-3},
                                              {"u_slip_spline", 1, 1e-2},
                                              {"u_migr_spline", 1, 1e-3},
                                              {"D12", 1, 1e-2},
                                              {"inclination_deg", 1, 1},
                                              {"mean_shear_stress", 1, 1e-1},
                                              {"omega_z", 1, 0.5}}};

TEST_F(TwoCellsTest, MetricsHaveAColumnPerCellAndThePairColumns)
{
  run(*pairDeck({0.0, 2.5, 1.25}, {0.0, 2.5, -1.25}), "pair");
  const auto t = table("pair");
  EXPECT_EQ(t.rows.size(), 3u); // t = 0, 0.05, 0.1: one row per output, not per cell
  EXPECT_EQ(std::count(t.columns.begin(), t.columns.end(), "cell"), 0);
  for (const char* column : {"time",
                             "D12_0",
                             "D12_1",
                             "x_c_0",
                             "x_c_1",
                             "u_slip_1",
                             "shape_change_rate_1",
                             "gmres_iterations",
                             "dx_0_1",
                             "dy_0_1",
                             "dz_0_1",
                             "distance_0_1",
                             "du_0_1",
                             "dv_0_1",
                             "dw_0_1",
                             "dslip_0_1",
                             "gap_0_1",
                             "min_angle_deg_0",
                             "min_angle_deg_1",
                             "max_edge_ratio_1",
                             "min_tension_0",
                             "wall_gap_per_h_1",
                             "max_distortion_1",
                             "min_stiffness_0"}) {
    EXPECT_EQ(std::count(t.columns.begin(), t.columns.end(), column), 1) << column;
  }
  EXPECT_EQ(t.columns.size(), 3u + 2u * 27u + 1u + 9u + 2u * 6u + 1u);
  EXPECT_EQ(t.columns.back(), "gap_per_h_0_1"); // the stability diagnostics come last
  // Separation and gap at t = 0: centres 2.5 apart; the level-1 icosphere has nodes on the
  // z axis, so the gap of the discrete surfaces is exactly the spheres' 0.5.
  EXPECT_NEAR(value(t, 0, "dz_0_1"), 2.5, 1e-12);
  EXPECT_NEAR(value(t, 0, "distance_0_1"), 2.5, 1e-12);
  EXPECT_NEAR(value(t, 0, "gap_0_1"), 0.5, 1e-12);
  // The same gap over the local element size: the level-1 icosphere's vertex edges are
  // 0.547-0.618 a long (edge ratio 1.131), so 0.5 a is 0.81-0.91 of an element.
  EXPECT_GT(value(t, 0, "gap_per_h_0_1"), 0.5 / 0.619);
  EXPECT_LT(value(t, 0, "gap_per_h_0_1"), 0.5 / 0.546);
  // The pair columns are the differences of the cell columns.
  const std::size_t last = t.rows.size() - 1;
  EXPECT_NEAR(value(t, last, "dz_0_1"), value(t, last, "z_c_0") - value(t, last, "z_c_1"), 1e-14);
  EXPECT_NEAR(value(t, last, "dslip_0_1"), value(t, last, "u_slip_0") - value(t, last, "u_slip_1"), 1e-14);
  const std::string summary = read("pair/summary.json");
  EXPECT_NE(summary.find("\"pairs\""), std::string::npos);
  EXPECT_NE(summary.find("\"relative u_slip\""), std::string::npos);
}

// Side by side (thesis Section 6.2): the configuration is its own mirror image under
// z -> -z with the cells exchanged, so the cells have equal x and y motion and opposite z
// motion (to kSymmetryTolerance, with the mirror-symmetric singular rule above).
TEST_F(TwoCellsTest, SideBySideCellsMoveAsMirrorImages)
{
  auto deck = pairDeck({0.0, 1.5, 1.25}, {0.0, 1.5, -1.25});
  deck->sublist("Discretisation").set("Singular quadrature points", kSymmetricSingularPoints);
  run(*deck, "side");
  const auto t = table("side");
  for (std::size_t row = 0; row < t.rows.size(); ++row) {
    for (const auto& m : kMirrored) {
      const std::string name = m.name;
      EXPECT_LE(mismatch(value(t, row, name + "_0"), value(t, row, name + "_1"), m.sign, m.scale), kSymmetryTolerance)
          << name << " at row " << row;
    }
  }
  // They do interact: they move apart (thesis Fig 6.4: U_z(1) - U_z(2) > 0).
  EXPECT_GT(value(t, t.rows.size() - 1, "dw_0_1"), 0.0);
}

// An arbitrary pair and its mirror image z -> -z: the same motion, mirrored (to
// kSymmetryTolerance, as above).
TEST_F(TwoCellsTest, MirrorImageDecksGiveMirrorImageResults)
{
  auto original = pairDeck({1.6, 1.8, 0.9}, {-1.5, 2.4, -0.7});
  auto mirrored = pairDeck({1.6, 1.8, -0.9}, {-1.5, 2.4, 0.7});
  for (auto* deck : {&original, &mirrored}) {
    (*deck)->sublist("Discretisation").set("Singular quadrature points", kSymmetricSingularPoints);
  }
  run(*original, "original");
  run(*mirrored, "mirrored");
  const auto a = table("original"), b = table("mirrored");
  ASSERT_EQ(a.rows.size(), b.rows.size());
  for (std::size_t row = 0; row < a.rows.size(); ++row) {
    for (const char* cell : {"_0", "_1"}) {
      for (const auto& m : kMirrored) {
        const std::string name = std::string(m.name) + cell;
        EXPECT_LE(mismatch(value(a, row, name), value(b, row, name), m.sign, m.scale), kSymmetryTolerance)
            << name << " at row " << row;
      }
    }
    EXPECT_LE(mismatch(value(a, row, "dz_0_1"), value(b, row, "dz_0_1"), -1, 1), kSymmetryTolerance);
    EXPECT_LE(mismatch(value(a, row, "gap_0_1"), value(b, row, "gap_0_1"), 1, 1), kSymmetryTolerance);
  }
}

// Far apart (in line, centres 22 radii apart: the thesis's Delta x0/a = 20) each cell moves
// as the isolated cell does, within 0.5% (the acceptance bound of the study). Measured:
// u_slip 0.44% above the isolated cell's (the other cell's disturbance, decaying like its
// stresslet and screened by the wall, still reaches 1e-4 of the shear there), D12, stress
// and rotation within 1e-4, height and reduced volume within 1e-6. The migration velocity
// (2e-4 here, differing by 4%) is left out: at this height it is too small for a relative
// comparison.
TEST_F(TwoCellsTest, FarApartEachCellMatchesTheIsolatedCell)
{
  const double h = 1.25; // the thesis's lower height
  run(*pairDeck({11.0, h, 0.0}, {-11.0, h, 0.0}), "pair");
  run(*pairDeck({0.0, h, 0.0}, {}, 1), "single");
  const auto pair = table("pair"), single = table("single");
  const std::size_t last = single.rows.size() - 1;
  ASSERT_EQ(pair.rows.size(), single.rows.size());
  for (const char* cell : {"_0", "_1"}) {
    for (const char* name :
         {"D12", "y_c", "u_slip", "u_slip_spline", "mean_shear_stress", "omega_z", "reduced_volume"}) {
      const double isolated = value(single, last, name);
      EXPECT_LE(std::abs(value(pair, last, std::string(name) + cell) - isolated), 5e-3 * std::abs(isolated))
          << name << cell << " vs the isolated " << isolated;
    }
  }
}

// Cells approaching each other stop the run cleanly below 'Cells/Minimum gap': status
// "too close", the reason names both cells, the gap and the time, and the metrics row and
// the checkpoint of that moment are written.
TEST_F(TwoCellsTest, CellsComingTooCloseStopTheRunWithOutputsAndCheckpoint)
{
  // Cell 0 above and behind cell 1, centres 1.8 apart in x and y: the upper cell moves
  // faster in the shear and catches up. The gap of the level-1 surfaces starts at 0.572
  // (the spheres' 0.546 plus the chord sag of the coarse facets) and shrinks to 0.559 by
  // t = 0.05 (measured; slower than the centres approach, because the facing sides lie
  // on the compressional axis of the shear and flatten).
  auto deck = pairDeck({-1.8, 3.3, 0.0}, {0.0, 1.5, 0.0});
  deck->sublist("Cells").set("Minimum gap", 0.565);
  const auto result = run(*deck, "close");
  EXPECT_EQ(result.status, "too close");
  EXPECT_LT(result.time, 0.05);
  const auto t = table("close");
  const std::size_t last = t.rows.size() - 1;
  EXPECT_DOUBLE_EQ(value(t, last, "time"), result.time);
  EXPECT_LT(value(t, last, "gap_0_1"), 0.565);
  EXPECT_GT(value(t, last, "gap_0_1"), 0.56); // stopped at the first step below, not later
  EXPECT_TRUE(fs::exists(root_ / "close" / "checkpoint.h5"));
  const std::string summary = read("close/summary.json");
  EXPECT_NE(summary.find("\"status\": \"too close\""), std::string::npos) << summary;
  std::ostringstream when;
  when << "Stopped at t = " << result.time << ": the surfaces of 'Cells/Cell 0' and 'Cells/Cell 1' are ";
  EXPECT_NE(summary.find(when.str()), std::string::npos) << summary;
  EXPECT_NE(summary.find("less than 'Cells/Minimum gap' = 0.565"), std::string::npos) << summary;
}

// The per-cell and pair columns survive a restart: the continued run writes the rows of
// the uninterrupted one, bit for bit (the pair metrics are functions of the restored
// state and centroid history).
TEST_F(TwoCellsTest, RestartReproducesTheUninterruptedRun)
{
  const auto whole = pairDeck({0.0, 1.5, 1.25}, {0.0, 1.5, -1.25});
  run(*whole, "whole");
  auto half = pairDeck({0.0, 1.5, 1.25}, {0.0, 1.5, -1.25});
  half->sublist("Time integration").set("End time", 0.05);
  run(*half, "split");
  EXPECT_EQ(run(*whole, "split", "split").status, "finished");
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
}

// 'Output/Wall shear stress/Isolated range' (Figs 6.6, 6.12): the wall areas of the pair's
// map below and above an isolated cell's range. A range that is the map's own minimum and
// maximum leaves nothing outside; a range above every value puts the whole grid below.
TEST_F(TwoCellsTest, WallAreasOutsideTheIsolatedCellsRange)
{
  const auto withMap = [](double lowest, double highest) {
    auto deck = pairDeck({0.0, 1.5, 1.25}, {0.0, 1.5, -1.25});
    auto& wall = deck->sublist("Output").sublist("Wall shear stress");
    wall.set("Enabled", true);
    wall.set("Spacing", 1.0);
    wall.set("Isolated range", realArray({lowest, highest}));
    deck->sublist("Time integration").set("End time", 0.04);
    deck->sublist("Output").set("Interval", 0.04);
    return deck;
  };
  run(*withMap(0.0, 100.0), "wide");
  const auto wide = table("wide");
  const std::size_t last = wide.rows.size() - 1;
  EXPECT_EQ(value(wide, last, "wall_area_below_isolated"), 0.0);
  EXPECT_EQ(value(wide, last, "wall_area_above_isolated"), 0.0);
  const double lowest = value(wide, last, "wall_stress_min"), highest = value(wide, last, "wall_stress_max");
  EXPECT_LT(lowest, 1.0);
  EXPECT_GT(highest, 1.0);
  run(*withMap(lowest, highest), "own");
  const auto own = table("own");
  EXPECT_EQ(value(own, last, "wall_area_below_isolated"), 0.0);
  EXPECT_EQ(value(own, last, "wall_area_above_isolated"), 0.0);
  run(*withMap(50.0, 100.0), "high");
  const auto high = table("high");
  // The grid (the default extents): 6 + 6 radii along the flow, 2 x 4 across.
  EXPECT_DOUBLE_EQ(value(high, last, "wall_area_below_isolated"), 12.0 * 8.0);
  EXPECT_NE(read("high/summary.json").find("area below the isolated cell's minimum"), std::string::npos);
  // A range that is not two numbers, smallest first, is refused.
  try {
    run(*withMap(2.0, 1.0), "bad");
    FAIL() << "a reversed range must be refused";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Output/Wall shear stress/Isolated range'"), std::string::npos) << e.what();
  }
}

TEST_F(TwoCellsTest, TouchingCellsAreRejectedAtTheStart)
{
  // Centres 2 radii apart along z: the spheres touch (the level-1 mesh has nodes on the
  // z axis, so the discrete surfaces touch exactly).
  try {
    run(*pairDeck({0.0, 2.0, 1.0}, {0.0, 2.0, -1.0}), "touching");
    FAIL() << "touching cells must be rejected";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Cells/Cell 0' and 'Cells/Cell 1' touch at the start"), std::string::npos)
        << e.what();
  }
  // Closer than the minimum gap counts as touching.
  try {
    run(*pairDeck({0.0, 2.0, 1.02}, {0.0, 2.0, -1.02}), "close");
    FAIL() << "cells 0.04 apart, below the default minimum gap 0.05, must be rejected";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not more than 'Cells/Minimum gap' = 0.05"), std::string::npos) << e.what();
  }
}

} // namespace
