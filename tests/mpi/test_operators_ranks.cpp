// The boundary-integral operators give the same velocities on 2 ranks as on 1.
//
// Two cells above the wall (a sphere and an ellipsoid, level 2) with a smooth load in shear
// flow. Every rank also computes the serial answer on a one-rank communicator and compares
// it with the distributed one. Each node's row is evaluated by the same arithmetic in the
// same order whichever rank owns it, so the explicit (lambda = 1) velocities agree to the
// last bit; the GMRES solve differs only in the rounding of its distributed dot products.
#include "capsula/testing/MpiTesting.hpp"
#include "capsula/testing/VectorDifference.hpp"

#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/KernelRegistry.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using namespace capsula;
using namespace capsula::operators;
using mesh::Vec3;

CellSurfaces twoCells(double lambdaSphere, double lambdaEllipsoid)
{
  mesh::Placement a, b;
  a.centre = Vec3(0.0, 1.3, 0.0);
  b.centre = Vec3(2.1, 1.1, 0.4);
  b.rotation = mesh::rotationAboutAxis(Vec3(0.3, 0.2, 1.0), 0.7);
  return CellSurfaces({mesh::makeSphere(2, 1.0, a), mesh::makeEllipsoid(2, Vec3(1.0, 0.5, 0.8), b)},
                      {lambdaSphere, lambdaEllipsoid});
}

std::vector<double> loadsOf(const CellSurfaces& surfaces)
{
  std::vector<double> loads;
  for (int c = 0; c < surfaces.numCells(); ++c) {
    for (int e = 0; e < surfaces.cell(c).numElements(); ++e) {
      const auto x = surfaces.cell(c).elementNodes(e);
      const auto s = mesh::evaluateSurfacePoint(x, mesh::shapeParameters(x), 1.0 / 3.0, 1.0 / 3.0);
      const Vec3 f = (2.0 + s.position[0]) * s.normal + Vec3(0.3, -0.2, 0.1 * s.position[2]);
      loads.insert(loads.end(), {f[0], f[1], f[2]});
    }
  }
  return loads;
}

using capsula::testing::relativeDifference;

void compareRanks(double lambdaSphere, double lambdaEllipsoid, double tolerance)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2) << "this test is registered to run on 2 ranks";
  const auto serial = Teuchos::rcp(new Teuchos::SerialComm<int>);
  const KernelRegistry registry = builtInKernels();
  SolverParameters solverParameters;
  solverParameters.tolerance = 1e-12;
  auto distributed = registry.create("Wall", comm, twoCells(lambdaSphere, lambdaEllipsoid), {}, solverParameters);
  auto reference = registry.create("Wall", serial, twoCells(lambdaSphere, lambdaEllipsoid), {}, solverParameters);
  EXPECT_TRUE(capsula::testing::allRanks(*comm, distributed->numOwnedNodes() < reference->numOwnedNodes()));

  const auto loads = loadsOf(reference->surfaces());
  FlowConditions flow;
  flow.capillaryNumber = 0.5;
  const auto u2 = distributed->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  const auto u1 = reference->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  const double nodes = relativeDifference(u1.velocities, u2.velocities);

  std::vector<double> probes;
  for (int p = 0; p < 7; ++p) {
    probes.insert(probes.end(), {-1.5 + 0.6 * p, 0.05 + 0.4 * p, 0.3 - 0.1 * p});
  }
  const auto flow2 =
      distributed->flowVelocity(probes, LoadDensity::constantOverElements(loads), u2.velocities.data(), flow);
  const auto flow1 =
      reference->flowVelocity(probes, LoadDensity::constantOverElements(loads), u1.velocities.data(), flow);
  const double points = relativeDifference(flow1, flow2);
  if (comm->getRank() == 0) {
    std::printf("lambda (%g, %g): 1 vs 2 ranks, node velocities %.2e, flow %.2e relative; GMRES %d / %d iterations\n",
                lambdaSphere, lambdaEllipsoid, nodes, points, u1.iterations, u2.iterations);
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, nodes < tolerance)) << nodes;
  EXPECT_TRUE(capsula::testing::allRanks(*comm, points < tolerance)) << points;
}

TEST(OperatorRanks, ExplicitVelocitiesMatchOneRank)
{
  compareRanks(1.0, 1.0, 1e-14); // identical arithmetic per row: bit for bit in practice
}

TEST(OperatorRanks, GmresVelocitiesMatchOneRank)
{
  // Different rounding in the distributed dot products only; GMRES solved to 1e-12.
  compareRanks(5.0, 0.5, 1e-12);
}

} // namespace

namespace {

// The warm start's history (WarmStartHistory) is replicated: every rank forms the same
// initial guess from the same global vectors. Two moves of the cells with the history on
// 2 ranks give what they give on 1, and every rank holds the same history.
TEST(OperatorRanks, WarmStartedVelocitiesMatchOneRank)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2) << "this test is registered to run on 2 ranks";
  const auto serial = Teuchos::rcp(new Teuchos::SerialComm<int>);
  const KernelRegistry registry = builtInKernels();
  SolverParameters solverParameters;
  solverParameters.tolerance = 1e-12;
  auto distributed = registry.create("Wall", comm, twoCells(5.0, 0.5), {}, solverParameters);
  auto reference = registry.create("Wall", serial, twoCells(5.0, 0.5), {}, solverParameters);
  const auto loads = loadsOf(reference->surfaces());
  FlowConditions flow;
  flow.capillaryNumber = 0.5;
  WarmStartHistory history1, history2;
  std::vector<double> x = reference->surfaces().positions();
  double worst = 0.0;
  int warmIterations = 0;
  for (int step = 0; step < 3; ++step) {
    const auto u2 = distributed->nodeVelocities(LoadDensity::constantOverElements(loads), flow, history2);
    const auto u1 = reference->nodeVelocities(LoadDensity::constantOverElements(loads), flow, history1);
    worst = std::max(worst, relativeDifference(u1.velocities, u2.velocities));
    warmIterations = u2.iterations;
    for (std::size_t k = 0; k < x.size(); ++k) {
      x[k] += 1e-2 * u1.velocities[k]; // the same new positions on both
    }
    distributed->setPositions(x.data());
    reference->setPositions(x.data());
  }
  // The history of rank 0 is the history of every rank (bit for bit: the same gathered numbers).
  std::vector<double> mine = history2.solutions(), root = mine;
  Teuchos::broadcast(*comm, 0, static_cast<int>(root.size()), root.data());
  if (comm->getRank() == 0) {
    std::printf("warm start: 1 vs 2 ranks, node velocities %.2e relative; last solve %d iterations\n", worst,
                warmIterations);
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, mine == root));
  EXPECT_TRUE(capsula::testing::allRanks(*comm, history2.size() == 3));
  // As GmresVelocitiesMatchOneRank: rounding of the distributed dot products, GMRES to 1e-12.
  EXPECT_TRUE(capsula::testing::allRanks(*comm, worst < 1e-12)) << worst;
}

} // namespace

namespace {

// The cell-block preconditioner ('Solver/Preconditioner' = "Cell blocks") does not depend on
// the number of ranks: a cell whose rows lie on both ranks gets its block summed over them
// (CellBlockPreconditioner.hpp). The sphere (642 nodes) of 966 is split 483 / 159 here.
TEST(OperatorRanks, CellBlockPreconditionedVelocitiesMatchOneRank)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2) << "this test is registered to run on 2 ranks";
  const auto serial = Teuchos::rcp(new Teuchos::SerialComm<int>);
  const auto cells = [] {
    mesh::Placement a, b, c;
    a.centre = Vec3(0.0, 1.3, 0.0);
    b.centre = Vec3(2.1, 1.1, 0.4);
    b.rotation = mesh::rotationAboutAxis(Vec3(0.3, 0.2, 1.0), 0.7);
    c.centre = Vec3(0.8, 1.2, 1.7);
    return CellSurfaces(
        {mesh::makeSphere(2, 1.0, a), mesh::makeEllipsoid(1, Vec3(1.0, 0.5, 0.8), b), mesh::makeSphere(1, 0.6, c)},
        {5.0, 0.5, 1.0});
  };
  const KernelRegistry registry = builtInKernels();
  SolverParameters solverParameters;
  solverParameters.tolerance = 1e-12;
  solverParameters.cellBlockPreconditioner = true;
  auto distributed = registry.create("Wall", comm, cells(), {}, solverParameters);
  auto reference = registry.create("Wall", serial, cells(), {}, solverParameters);
  EXPECT_TRUE(capsula::testing::allRanks(*comm, distributed->numOwnedNodes() == 483));
  const auto loads = loadsOf(reference->surfaces());
  FlowConditions flow;
  flow.capillaryNumber = 0.5;
  const auto u2 = distributed->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  const auto u1 = reference->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  const double difference = relativeDifference(u1.velocities, u2.velocities);
  if (comm->getRank() == 0) {
    std::printf("cell blocks: 1 vs 2 ranks, node velocities %.2e relative; flexible GMRES %d / %d iterations\n",
                difference, u1.iterations, u2.iterations);
  }
  // The same preconditioner bit for bit; what differs is the rounding of the distributed dot
  // products, as in GmresVelocitiesMatchOneRank, and so does nothing else: equal iterations.
  EXPECT_TRUE(capsula::testing::allRanks(*comm, difference < 1e-12)) << difference;
  EXPECT_TRUE(capsula::testing::allRanks(*comm, u1.iterations == u2.iterations));
}

} // namespace
