#include "SceneTestDecks.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/scene/CellKinematics.hpp>
#include <capsula/scene/NodesAboveWall.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SceneDescription.hpp>
#include <capsula/scene/UnfoldedMembranes.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace {

namespace core = capsula::core;
namespace mesh = capsula::mesh;
namespace scene = capsula::scene;
using scene::testing::makeScene;
using scene::testing::smallDeck;

bool anyTermContains(const scene::Scene& s, const std::string& piece)
{
  return std::any_of(s.terms().begin(), s.terms().end(),
                     [&](const std::string& t) { return t.find(piece) != std::string::npos; });
}

// Largest |u_i - u_inf(x_i)| over the nodes, u_inf = (y, 0, 0).
double disturbance(const std::vector<double>& x, const std::vector<double>& u)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < x.size(); i += 3) {
    largest = std::max({largest, std::abs(u[i] - x[i + 1]), std::abs(u[i + 1]), std::abs(u[i + 2])});
  }
  return largest;
}

TEST(Scene, FreeSpaceUnitViscosityRatioBuildsNoSolverAndNoWallKernel)
{
  auto deck = smallDeck(1, 0.0, false);
  auto s = makeScene(*deck);
  EXPECT_EQ(s.kernelName().find("wall"), std::string::npos) << s.kernelName();
  EXPECT_TRUE(anyTermContains(s, "kernel: FreeSpace"));
  EXPECT_TRUE(anyTermContains(s, "no double layer, no linear solve"));
  EXPECT_FALSE(anyTermContains(s, "GMRES"));
  EXPECT_FALSE(anyTermContains(s, "constraint"));
  EXPECT_FALSE(s.hasConstraints());
  // Evaluating the velocity never starts the GMRES solve.
  const auto gmres = core::timer("Viscosity-ratio GMRES solve");
  const int callsBefore = gmres->numCalls();
  std::vector<double> u;
  s.velocity(0.0, s.initialPositions(), u);
  const auto fields = s.evaluate(0.0, s.initialPositions());
  EXPECT_EQ(gmres->numCalls(), callsBefore);
  EXPECT_EQ(fields.gmresIterations, 0);
  // An unstressed capsule carries no load: every node moves with the undisturbed shear
  // (the loads are round-off, ~1e-15, from comparing a shape with itself).
  EXPECT_LT(disturbance(s.initialPositions(), u), 1e-12);
}

TEST(Scene, WallAndViscosityContrastBuildTheWallKernelAndTheSolve)
{
  auto deck = smallDeck(0, 2.0, true, [](Teuchos::ParameterList& d) {
    d.sublist("Flow").set("Viscosity ratio", 5.0);
    d.sublist("Cells").sublist("Cell 0").set("Fixed height", true);
  });
  auto s = makeScene(*deck);
  EXPECT_TRUE(anyTermContains(s, "kernel: Wall"));
  EXPECT_TRUE(anyTermContains(s, "Belos Block GMRES")); // the default 'Solver/Method'
  EXPECT_TRUE(anyTermContains(s, "constraint: fixed centroid height of Cells/Cell 0"));
  EXPECT_TRUE(s.hasConstraints());
  const auto gmres = core::timer("Viscosity-ratio GMRES solve");
  const int callsBefore = gmres->numCalls();
  // The undisturbed flow alone gives the equation a right-hand side to solve for.
  const auto fields = s.evaluate(0.0, s.initialPositions());
  EXPECT_GT(gmres->numCalls(), callsBefore);
  EXPECT_GT(fields.gmresIterations, 0);
}

// 'Cells/Cell k/Viscosity ratio' (0: 'Flow/Viscosity ratio'). Two level-1 spheres 40 radii
// apart in unbounded shear: with their own ratios 5 and 1, each moves as it would alone with
// that ratio, up to their interaction, the weak far field of a prestressed sphere (measured
// largest difference 1.3e-6, bound 1e-4); the two ratios' motions differ by 0.31 (measured), so
// a ratio given to the wrong cell, or the flow's used for both, fails. A scene whose cells all
// carry the flow's ratio as their own is the same scene as one that only sets the flow's.
TEST(Scene, PerCellViscosityRatiosAreEachCellsOwn)
{
  const auto twoCells = [](double flowRatio, double ratio0, double ratio1) {
    return smallDeck(1, 0.0, false, [&](Teuchos::ParameterList& d) {
      d.sublist("Flow").set("Viscosity ratio", flowRatio);
      auto& cells = d.sublist("Cells");
      cells.sublist("Cell 0").set("Viscosity ratio", ratio0);
      cells.sublist("Cell 1").set("Center", scene::testing::realArray({0.0, 0.0, 40.0}));
      cells.sublist("Cell 1").set("Mesh level", 1);
      cells.sublist("Cell 1").set("Viscosity ratio", ratio1);
    });
  };
  const auto alone = [](double ratio, double z) {
    return smallDeck(1, 0.0, false, [&](Teuchos::ParameterList& d) {
      d.sublist("Flow").set("Viscosity ratio", ratio);
      d.sublist("Cells").sublist("Cell 0").set("Center", scene::testing::realArray({0.0, 0.0, z}));
    });
  };
  const auto velocityOf = [](const Teuchos::ParameterList& deck) {
    auto s = makeScene(deck);
    std::vector<double> u;
    s.velocity(0.0, s.initialPositions(), u);
    return u;
  };
  // Tank-treading needs a load: a prestressed membrane (without it every node moves with u_inf).
  const auto prestress = [](Teuchos::RCP<Teuchos::ParameterList> deck) {
    for (const char* cell : {"Cell 0", "Cell 1"}) {
      if (deck->sublist("Cells").isSublist(cell)) {
        deck->sublist("Cells").sublist(cell).set("Prestress", 0.05);
      }
    }
    return deck;
  };
  const auto mixed = prestress(twoCells(1.0, 5.0, 0.0));
  auto mixedScene = makeScene(*mixed);
  EXPECT_TRUE(anyTermContains(mixedScene, "viscosity ratio 5 (Cell 0), 1 (Cell 1): double layer"));
  const auto u = velocityOf(*mixed);
  const auto u5 = velocityOf(*prestress(alone(5.0, 0.0)));
  const auto u1 = velocityOf(*prestress(alone(1.0, 40.0)));
  const std::size_t half = u5.size();
  ASSERT_EQ(u.size(), 2 * half);
  double interaction = 0.0, contrast = 0.0;
  for (std::size_t i = 0; i < half; ++i) {
    interaction = std::max({interaction, std::abs(u[i] - u5[i]), std::abs(u[half + i] - u1[i])});
    contrast = std::max(contrast, std::abs(u5[i] - u1[i]));
  }
  EXPECT_LT(interaction, 1e-4);
  EXPECT_GT(contrast, 0.1);
  // Own ratios equal to the flow's: the same operator, the same velocities.
  const auto own = velocityOf(*prestress(twoCells(1.0, 5.0, 5.0)));
  const auto flow = velocityOf(*prestress(twoCells(5.0, 0.0, 0.0)));
  for (std::size_t i = 0; i < own.size(); ++i) {
    EXPECT_NEAR(own[i], flow[i], 1e-12);
  }
}

TEST(Scene, PrestressedSphereMovesWithTheUndisturbedFlow)
{
  // ERRATA (eq 3.37): the single layer of a uniform normal load on a sphere vanishes, so a
  // prestressed spherical capsule is carried by the shear undisturbed, free or near the
  // wall (the wall kernel is a Stokes flow in x too). The load is 2 T / r ~ 0.1 here; the
  // velocity disturbance left is the discretisation error of the load and the single
  // layer, second order in h: measured 9.2e-3 (level 1) and 2.1e-3 (level 2), a ratio of
  // 4.3, so >= 3.5 (order >= 1.8) is required, and below 2.5e-3 at level 2.
  for (bool wall : {false, true}) {
    std::vector<double> errors;
    for (int level : {1, 2}) {
      auto deck = smallDeck(level, wall ? 2.0 : 0.0, wall, [](Teuchos::ParameterList& d) {
        d.sublist("Cells").sublist("Cell 0").set("Prestress", 0.05);
      });
      auto s = makeScene(*deck);
      EXPECT_TRUE(anyTermContains(s, "prestressed reference, alpha = 0.05"));
      std::vector<double> u;
      s.velocity(0.0, s.initialPositions(), u);
      errors.push_back(disturbance(s.initialPositions(), u));
      // The load itself is not small: the check has teeth.
      double load = 0.0;
      for (double f : s.elementLoads()) {
        load = std::max(load, std::abs(f));
      }
      EXPECT_GT(load, 0.05);
    }
    EXPECT_GT(errors[0] / errors[1], 3.5) << "wall " << wall;
    EXPECT_LT(errors[1], 2.5e-3) << "wall " << wall;
  }
}

TEST(Scene, FixedHeightHoldsTheCentroidStill)
{
  // Near the wall a deformed cell migrates; the constraint removes exactly its centroid
  // rise rate (round-off), leaving the horizontal motion alone.
  auto deck = smallDeck(
      1, 1.5, true, [](Teuchos::ParameterList& d) { d.sublist("Cells").sublist("Cell 0").set("Fixed height", true); });
  auto s = makeScene(*deck);
  std::vector<double> x = s.initialPositions();
  for (std::size_t i = 0; i < x.size(); i += 3) { // an ellipsoid tilted in xy
    const double px = x[i], py = x[i + 1] - 1.5;
    x[i] = 1.2 * px + 0.1 * py;
    x[i + 1] = 1.5 + 0.85 * py + 0.1 * px;
  }
  std::vector<double> free;
  s.velocity(0.0, x, free);
  const mesh::Vec3 freeRate = scene::centroidVelocity(s.cell(0), free.data());
  std::vector<double> held = free;
  s.constrain(x, held);
  const mesh::Vec3 heldRate = scene::centroidVelocity(s.cell(0), held.data());
  EXPECT_GT(std::abs(freeRate[1]), 1e-4); // there is something to remove
  EXPECT_NEAR(heldRate[1], 0.0, 1e-14);
  EXPECT_NEAR(heldRate[0], freeRate[0], 1e-14);
}

TEST(Scene, RejectsCellsThatCrossTheWallOrOverlap)
{
  const auto message = [](const Teuchos::ParameterList& deck) -> std::string {
    try {
      makeScene(deck);
    } catch (const core::InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message(*smallDeck(1, 0.8, true)).find("'Cells/Cell 0' crosses the wall"), std::string::npos);
  // Without the wall the same cell is fine.
  EXPECT_EQ(message(*smallDeck(1, 0.8, false)), "");
  const auto overlapping = smallDeck(1, 2.0, true, [](Teuchos::ParameterList& d) {
    d.sublist("Cells").sublist("Cell 1").set("Center", scene::testing::realArray({1.5, 2.0, 0.0}));
    d.sublist("Cells").sublist("Cell 1").set("Mesh level", 1);
  });
  EXPECT_NE(message(*overlapping).find("'Cells/Cell 0' and 'Cells/Cell 1' overlap"), std::string::npos);
}

TEST(Scene, ReportsANodeReachingTheWallDuringTheRun)
{
  auto s = makeScene(*smallDeck(1, 2.0, true));
  std::vector<double> x = s.initialPositions();
  x[1] = -0.01;
  std::vector<double> u;
  try {
    s.velocity(1.25, x, u);
    FAIL() << "a node below the wall must stop the run";
  } catch (const core::NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("At t = 1.25 node 0 of 'Cells/Cell 0' reached the wall"), std::string::npos) << what;
  }
  x[1] = NAN;
  EXPECT_THROW(s.velocity(1.25, x, u), core::NumericalError);
}

// The runs' domain check (NodesAboveWall.hpp): a stage state with a node on or below the wall
// (or a NaN height) is outside the model, named by cell and node, with the hint that fits the
// deck; a state above it, or any state without a wall, passes.
TEST(Scene, DomainCheckNamesTheNodeThroughTheWall)
{
  for (const bool contact : {false, true}) {
    auto s = makeScene(*smallDeck(1, 2.0, true, [&](Teuchos::ParameterList& d) {
      d.sublist("Cells").sublist("Cell 1").set("Center", scene::testing::realArray({3.0, 2.0, 0.0}));
      d.sublist("Cells").sublist("Cell 1").set("Mesh level", 1);
      d.sublist("Contact").set("Enabled", contact);
    }));
    std::vector<double> x = s.initialPositions();
    EXPECT_NO_THROW(scene::requireNodesAboveWall(s, x));
    const std::size_t node = 7;
    for (const double y : {0.0, -0.2, static_cast<double>(NAN)}) {
      x[3 * (static_cast<std::size_t>(s.nodeOffset(1)) + node) + 1] = y;
      try {
        scene::requireNodesAboveWall(s, x);
        ADD_FAILURE() << "y = " << y << " must be outside";
      } catch (const capsula::timeint::StateOutsideDomain& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("node 7 of 'Cells/Cell 1' reached the wall"), std::string::npos) << what;
        EXPECT_NE(what.find(contact ? "'Contact/Strength'" : "unless 'Contact/Enabled' is true"), std::string::npos)
            << what;
      }
    }
  }
  auto free = makeScene(*smallDeck(1, 0.8, false));
  std::vector<double> x = free.initialPositions();
  x[1] = -5.0;
  EXPECT_NO_THROW(scene::requireNodesAboveWall(free, x));
}

// The other half of the domain check (UnfoldedMembranes.hpp), and the right-hand side: a
// state that folds elements of a cell is outside the model, named by cell
// and node, both in the check and in velocity() (where the integrator rejects the attempt
// instead of ending the run); the unfolded start passes.
TEST(Scene, FoldedMembraneIsOutsideTheModel)
{
  auto s = makeScene(*smallDeck(1, 2.0, false, [&](Teuchos::ParameterList& d) {
    d.sublist("Cells").sublist("Cell 1").set("Center", scene::testing::realArray({3.0, 2.0, 0.0}));
    d.sublist("Cells").sublist("Cell 1").set("Mesh level", 2);
  }));
  std::vector<double> x = s.initialPositions();
  EXPECT_NO_THROW(scene::requireUnfoldedMembranes(s, x));
  const std::size_t first = 3 * static_cast<std::size_t>(s.nodeOffset(1));
  // Node 0 (a vertex, at x = 3 on the sphere) slides along the surface by 0.6, twice the
  // level-2 edge, past its neighbours: the elements it moves over turn inside out.
  ASSERT_EQ(x[first], 3.0);
  x[first] += 0.6;
  const auto outside = [](const std::function<void()>& action) {
    try {
      action();
    } catch (const capsula::timeint::StateOutsideDomain& e) {
      return std::string(e.what());
    }
    return std::string("(nothing thrown)");
  };
  const std::string checked = outside([&] { scene::requireUnfoldedMembranes(s, x); });
  EXPECT_NE(checked.find("the membrane of 'Cells/Cell 1' failed: the membrane is folded at node "), std::string::npos)
      << checked;
  std::vector<double> u;
  const std::string evaluated = outside([&] { s.velocity(0.5, x, u); });
  EXPECT_NE(evaluated.find("At t = 0.5, the membrane of 'Cells/Cell 1' failed: the membrane is folded at node "),
            std::string::npos)
      << evaluated;
}

} // namespace
