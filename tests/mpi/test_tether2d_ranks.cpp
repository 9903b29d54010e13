// The 2D boundary-integral solve and a short tethered run on 2 ranks agree with the same
// computation on one rank (each rank repeats it with a serial communicator).
#include "capsula/testing/MpiTesting.hpp"

#include <capsula/contour/InitialShapes.hpp>
#include <capsula/core/Deck.hpp>
#include <capsula/scene2d/InterfaceVelocity2D.hpp>
#include <capsula/scene2d/Tether2DDeck.hpp>
#include <capsula/scene2d/TetherRun2D.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace capsula;

Teuchos::RCP<const Teuchos::Comm<int>> serial()
{
  return Teuchos::rcp(new Teuchos::SerialComm<int>);
}

contour::Contour tetheredEllipse()
{
  contour::EllipseShape shape;
  shape.aspectRatio = 0.5;
  shape.centre = Eigen::Vector2d(0.0, 1.6);
  shape.firstNodeAngle = -M_PI / 2.0;
  contour::ContourOptions options;
  options.closure = contour::Closure::Tethered;
  return contour::Contour(contour::ellipseNodes(41, shape), options); // 41: the ranks own 21 + 20
}

Teuchos::ParameterList deck(double lambda)
{
  const auto valid = scene2d::validTether2DParameters();
  Teuchos::ParameterList d("tether2d");
  for (const std::string a :
       {"Cell/Number of points=33", "Flow/Capillary number=0.1", "Tether/Minimum preparation time=0.125",
        "Tether/Maximum preparation time=0.25", "Time integration/End time=0.25", "Output/Interval=0.125"}) {
    core::applyOverride(d, *valid, a);
  }
  d.sublist("Flow").set("Viscosity ratio", lambda);
  core::validateDeck(d, *valid, "test deck");
  return d;
}

} // namespace

TEST(Tether2DRanks, NodeVelocitiesDoNotDependOnTheRankCount)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2);
  const contour::Contour c = tetheredEllipse();
  const auto load = [](const contour::ContourPoint& p, int, double) -> Eigen::Vector2d {
    return 0.4 * p.curvature * p.normal + 0.1 * p.position.x() * p.tangent;
  };
  bool ok = true;
  for (const double lambda : {1.0, 5.0}) {
    scene2d::FlowConditions2D flow;
    flow.capillaryNumber = 0.1;
    flow.viscosityRatio = lambda;
    operators::SolverParameters solver;
    solver.tolerance = 1e-12;
    auto parallel = scene2d::makeInterfaceVelocity2D(true, comm, c.numberOfNodes(), {}, solver);
    auto alone = scene2d::makeInterfaceVelocity2D(true, serial(), c.numberOfNodes(), {}, solver);
    ok = ok && parallel->distribution().numOwnedNodes() == (comm->getRank() == 0 ? 21 : 20);
    const auto u2 = parallel->nodeVelocities(c, load, flow, {0}).velocities;
    const auto u1 = alone->nodeVelocities(c, load, flow, {0}).velocities;
    double largest = 0.0, difference = 0.0;
    for (std::size_t k = 0; k < u1.size(); ++k) {
      largest = std::max(largest, std::abs(u1[k]));
      difference = std::max(difference, std::abs(u2[k] - u1[k]));
    }
    // lambda = 1: every row is summed in the same order on any rank: bit for bit.
    // lambda = 5: GMRES's inner products are reduced over ranks in another order; both
    // stop at 1e-12 relative residual, so the solutions agree to ~1e-11.
    ok = ok && (lambda == 1.0 ? difference == 0.0 : difference < 1e-10 * largest);
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, ok));
}

TEST(Tether2DRanks, TetheredRunDoesNotDependOnTheRankCount)
{
  const auto comm = Tpetra::getDefaultComm();
  bool ok = true;
  for (const double lambda : {1.0, 3.0}) {
    scene2d::TetherRun2D parallel(comm, deck(lambda), nullptr);
    scene2d::TetherRun2D alone(serial(), deck(lambda), nullptr);
    const auto a = parallel.run("", std::nullopt);
    const auto b = alone.run("", std::nullopt);
    // lambda = 1: identical velocities, hence identical steps. lambda = 3: round-off in
    // GMRES (1e-11) may nudge the adaptive steps; 1e-8 is far below any physical change.
    const double tolerance = lambda == 1.0 ? 0.0 : 1e-8;
    ok = ok && a.tethered && b.tethered;
    ok = ok && std::abs(a.final.tetherForce - b.final.tetherForce) <= tolerance;
    ok = ok && std::abs(a.final.D12 - b.final.D12) <= tolerance;
    ok = ok && std::abs(a.final.areaDrift - b.final.areaDrift) <= tolerance;
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, ok));
}

TEST(Tether2DRanks, StiffTetheredRunDoesNotDependOnTheRankCount)
{
  // The stiff methods' Jacobian gathers the single layer's rows in a fixed order and every
  // rank runs GMRES on the whole (replicated) vectors, so at lambda = 1 the runs are the
  // same bit for bit: ROS34PW2, and Auto at Ca = 0.002, where it switches to ROS34PW2.
  const auto comm = Tpetra::getDefaultComm();
  bool ok = true;
  for (const std::string method : {"ROS34PW2", "Auto"}) {
    Teuchos::ParameterList d = deck(1.0);
    d.sublist("Time integration").set("Method", method);
    if (method == "Auto") {
      d.sublist("Flow").set("Capillary number", 0.002);
    }
    scene2d::TetherRun2D parallel(comm, d, nullptr);
    scene2d::TetherRun2D alone(serial(), d, nullptr);
    const auto a = parallel.run("", std::nullopt);
    const auto b = alone.run("", std::nullopt);
    ok = ok && a.tethered && b.tethered && a.steps == b.steps;
    ok = ok && a.final.tetherForce == b.final.tetherForce && a.maxTetherForce == b.maxTetherForce;
    ok = ok && a.final.D12 == b.final.D12 && a.final.areaDrift == b.final.areaDrift;
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, ok));
}
