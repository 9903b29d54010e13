#include "SceneTestDecks.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/scene/CellKinematics.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SceneDescription.hpp>
#include <capsula/scene/WallShearStressMap.hpp>
#include <capsula/operators/WallShearStress.hpp>

#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
  EXPECT_TRUE(anyTermContains(s, "Belos GMRES"));
  EXPECT_TRUE(anyTermContains(s, "constraint: fixed centroid height of Cells/Cell 0"));
  EXPECT_TRUE(s.hasConstraints());
  const auto gmres = core::timer("Viscosity-ratio GMRES solve");
  const int callsBefore = gmres->numCalls();
  // The undisturbed flow alone gives the equation a right-hand side to solve for.
  const auto fields = s.evaluate(0.0, s.initialPositions());
  EXPECT_GT(gmres->numCalls(), callsBefore);
  EXPECT_GT(fields.gmresIterations, 0);
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
  auto deck = smallDeck(1, 1.5, true, [](Teuchos::ParameterList& d) {
    d.sublist("Cells").sublist("Cell 0").set("Fixed height", true);
  });
  auto s = makeScene(*deck);
  std::vector<double> x = s.initialPositions();
  for (std::size_t i = 0; i < x.size(); i += 3) {   // an ellipsoid tilted in xy
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
  EXPECT_GT(std::abs(freeRate[1]), 1e-4);       // there is something to remove
  EXPECT_NEAR(heldRate[1], 0.0, 1e-14);
  EXPECT_NEAR(heldRate[0], freeRate[0], 1e-14);
}

TEST(Scene, WallShearStressConvergesAtFourthOrderAndMatchesTheOperators)
{
  // A stretched prestressed cell at h/a = 1.6 disturbs the wall stress. The stencil is
  // fourth order: halving the step h (0.04, 0.02, 0.01) divides the change by 16 in the
  // limit; with the top stencil point at a quarter of the gap the next term still counts
  // (measured 11.1), and a third-order stencil would give 8: > 10 required. Without the
  // adaptive near-singular quadrature (distance 0) the operators' own stencil (which also
  // evaluates u(0) = 0) must agree to the truncation error at h = 0.02, measured below
  // 1e-5: 5e-5 allowed.
  auto s = makeScene(*smallDeck(1, 1.6, true, [](Teuchos::ParameterList& d) {
    d.sublist("Cells").sublist("Cell 0").set("Prestress", 0.05);
  }));
  std::vector<double> x = s.initialPositions();
  for (std::size_t i = 0; i < x.size(); i += 3) {   // stretch it so it disturbs the flow
    x[i] *= 1.2;
  }
  const auto fields = s.evaluate(0.0, x);
  const auto grid = scene::WallGrid::around(0.0, 0.0, 2.0, 2.0, 1.0, 0.5);
  const auto at = [&](double step) {
    return scene::wallShearStressOnGrid(s.solver(), grid, step, capsula::operators::LoadDensity(fields.loadDensity.data()),
                                        fields.solverVelocities.data(), s.flow());
  };
  const auto coarse = at(0.04), medium = at(0.02), fine = at(0.01);
  double firstChange = 0.0, secondChange = 0.0;
  for (std::size_t k = 0; k < fine.magnitude.size(); ++k) {
    firstChange = std::max(firstChange, std::abs(coarse.dudy[k] - medium.dudy[k]));
    secondChange = std::max(secondChange, std::abs(medium.dudy[k] - fine.dudy[k]));
  }
  EXPECT_GT(firstChange / secondChange, 10.0) << firstChange << " then " << secondChange;
  std::vector<double> wallPoints;
  for (const auto& p : grid.nodes()) {
    wallPoints.insert(wallPoints.end(), {p[0], p[2]});
  }
  const auto theirs = capsula::operators::wallShearStress(s.solver(), wallPoints, 0.02, capsula::operators::LoadDensity(fields.loadDensity.data()),
                                                          fields.solverVelocities.data(), s.flow());
  double lowest = HUGE_VAL, highest = 0.0;
  for (std::size_t k = 0; k < fine.magnitude.size(); ++k) {
    EXPECT_NEAR(fine.dudy[k], theirs.dudy[k], 5e-5);
    EXPECT_NEAR(fine.dwdy[k], theirs.dwdy[k], 5e-5);
    lowest = std::min(lowest, fine.magnitude[k]);
    highest = std::max(highest, fine.magnitude[k]);
  }
  // The cell does disturb the wall stress (ambient 1): not a vacuous comparison.
  EXPECT_LT(lowest, 0.99);
  EXPECT_GT(highest, 1.01);
}

TEST(Scene, WallShearStressOfTheUndisturbedFlowIsOne)
{
  // An unstressed cell carries no load: the flow is u = (y, 0, 0) and the stencil is exact
  // for it (fourth order, linear field), so sigma = 1 to round-off.
  auto s = makeScene(*smallDeck(1, 1.6, true));
  const auto fields = s.evaluate(0.0, s.initialPositions());
  const auto grid = scene::WallGrid::around(0.0, 0.0, 1.0, 1.0, 1.0, 0.5);
  const auto stress = scene::wallShearStressOnGrid(s.solver(), grid, 0.03, capsula::operators::LoadDensity(fields.loadDensity.data()),
                                                   fields.solverVelocities.data(), s.flow());
  for (double sigma : stress.magnitude) {
    EXPECT_NEAR(sigma, 1.0, 1e-10);
  }
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

} // namespace
