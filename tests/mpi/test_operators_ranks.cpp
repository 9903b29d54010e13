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
#include <capsula/operators/CellBlockPreconditioner.hpp>
#include <capsula/operators/KernelRegistry.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

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

// Each cell block is held by one rank, balanced by size whichever rank owns the cell's rows
// (CellBlockPreconditioner.hpp). Four cells of 2 nodes, the third without a block (scale 0):
// rows of cells 0 and 1 on rank 0, of cells 2 and 3 on rank 1; the three blocks go to ranks
// 0, 1, 1, so cell 1's rows travel from rank 0 to its holder. The result is bit for bit the
// one-rank preconditioner's: the same rows, the same single-precision LU, sums with zeros.
TEST(OperatorRanks, CellBlocksAreBalancedOverTheRanksAndApplyAsOnOneRank)
{
  const auto comm = Tpetra::getDefaultComm();
  const auto serial = Teuchos::rcp(new Teuchos::SerialComm<int>);
  const std::vector<int> offsets = {0, 2, 4, 6, 8};
  const std::vector<double> scale = {0.25, 0.2, 0.0, 0.3}; // P_c's diagonal 1 - 2 s far from 0
  // Row r (of the cell's 6) against column k of cell c: diagonally dominant, nonsingular P_c.
  const auto entry = [](int c, int r, int k) { return (r == k ? 2.0 : 0.0) + 0.1 * std::sin(1.0 + r + 2.0 * k + c); };
  const auto build = [&](const Teuchos::RCP<const Teuchos::Comm<int>>& on, std::vector<int>& asked) {
    const auto map = Teuchos::rcp(new Tpetra::Map<>(24, 0, on));
    const int firstNode = static_cast<int>(map->getMinGlobalIndex() / 3);
    const int endNode = firstNode + static_cast<int>(map->getNodeNumElements() / 3);
    return std::make_unique<CellBlockPreconditioner>(
        map, offsets, scale, [&, firstNode, endNode](int c, std::vector<double>& rows) {
          asked.push_back(c);
          const int first = std::max(firstNode, offsets[c]), end = std::min(endNode, offsets[c + 1]);
          rows.clear();
          for (int node = first; node < end; ++node) {
            for (int i = 0; i < 3; ++i) {
              for (int k = 0; k < 6; ++k) {
                rows.push_back(entry(c, 3 * (node - offsets[c]) + i, k));
              }
            }
          }
          return end - first;
        });
  };
  std::vector<int> askedHere, askedAlone;
  const auto distributed = build(comm, askedHere);
  const auto alone = build(serial, askedAlone);
  const int rank = comm->getRank();
  bool ok = distributed->heldBlocks() == (rank == 0 ? 1 : 2) && alone->heldBlocks() == 3;
  // Each rank computes the rows it owns, of the cells with a block only.
  ok = ok && askedHere == (rank == 0 ? std::vector<int>{0, 1} : std::vector<int>{3});
  const auto apply = [](const CellBlockPreconditioner& M) {
    Tpetra::MultiVector<double> x(M.getDomainMap(), 1), y(M.getRangeMap(), 1);
    auto in = x.getDataNonConst(0);
    for (decltype(in.size()) k = 0; k < in.size(); ++k) {
      in[k] = std::cos(0.7 * static_cast<double>(M.getDomainMap()->getGlobalElement(static_cast<int>(k))));
    }
    M.apply(x, y);
    std::vector<double> out(24, 0.0);
    const auto data = y.getData(0);
    for (decltype(data.size()) k = 0; k < data.size(); ++k) {
      out[static_cast<std::size_t>(M.getRangeMap()->getGlobalElement(static_cast<int>(k)))] = data[k];
    }
    return out;
  };
  std::vector<double> mine = apply(*distributed), all(24);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 24, mine.data(), all.data());
  const std::vector<double> reference = apply(*alone);
  ok = ok && all == reference;
  ok = ok && all[12] == std::cos(0.7 * 12) && all[17] == std::cos(0.7 * 17); // cell 2: identity
  EXPECT_TRUE(capsula::testing::allRanks(*comm, ok));
}

} // namespace
