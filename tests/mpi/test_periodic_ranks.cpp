// The periodic kernels give the same velocities on 2 ranks as on 1. Every rank sums all
// quadrature points for the node rows it owns (as the direct sums and the treecode do), so
// the rows are those of one rank up to the Ewald grid: the spectral sum fits its grid to the
// heights of the sources and of the rank's own targets, and another grid moves a value by
// up to its tolerance (measured 0.05-0.3 tol, tests/unit/ewald). With the sums at 1e-10 of
// the largest velocity, 1e-9 bounds the difference; a rank that missed another's cells or
// rows would be off by O(1).
#include "capsula/testing/MpiTesting.hpp"

#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/periodic/PeriodicKernelLibrary.hpp>

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

// Two cells 0.2 apart across the boundary x = 0 of a box 3.2 x 2.8.
CellSurfaces twoCells(double lambda)
{
  return CellSurfaces({mesh::makeSphere(1, 0.5, {Vec3(2.9, 1.0, 0.3)}),
                       mesh::makeEllipsoid(1, Vec3(0.6, 0.4, 0.5), {Vec3(1.0, 1.2, 0.5)})},
                      {lambda, lambda});
}

std::vector<double> loadsOf(const CellSurfaces& surfaces)
{
  std::vector<double> loads;
  for (int c = 0; c < surfaces.numCells(); ++c) {
    for (int e = 0; e < surfaces.cell(c).numElements(); ++e) {
      const auto x = surfaces.cell(c).elementNodes(e);
      const auto s = mesh::evaluateSurfacePoint(x, mesh::shapeParameters(x), 1.0 / 3.0, 1.0 / 3.0);
      const Vec3 f = (2.0 + s.position[1]) * s.normal + Vec3(0.3, -0.2, 0.1 * s.normal[2]);
      loads.insert(loads.end(), {f[0], f[1], f[2]});
    }
  }
  return loads;
}

// `channelHeight` > 0: the channel 0 < y < H (needs the wall).
void compareRanks(const std::string& kernel, bool wall, double lambda, double channelHeight = 0.0)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2) << "this test is registered to run on 2 ranks";
  const auto serial = Teuchos::rcp(new Teuchos::SerialComm<int>);
  KernelRegistry registry = builtInKernels();
  periodic::registerPeriodicKernels(registry);
  const domain::Domain box(domain::DomainShape{wall, channelHeight, 3.2, 2.8});
  Teuchos::ParameterList settings;
  settings.set("Tolerance", 1e-10);
  SolverParameters solverParameters;
  solverParameters.tolerance = 1e-12;
  auto distributed = registry.create(kernel, comm, twoCells(lambda), {}, solverParameters, settings, box);
  auto reference = registry.create(kernel, serial, twoCells(lambda), {}, solverParameters, settings, box);
  EXPECT_TRUE(capsula::testing::allRanks(*comm, distributed->numOwnedNodes() < reference->numOwnedNodes()));
  const auto loads = loadsOf(reference->surfaces());
  FlowConditions flow;
  flow.capillaryNumber = 0.5;
  const auto u2 = distributed->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  const auto u1 = reference->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  // Flow probes, some across the boundary and one a period away.
  const std::vector<double> probes = {1.7, 1.1, 1.4, 3.5, 0.3, 2.6, -1.4, 2.0, 0.9, 6.4 + 1.7, 1.8, 1.4};
  const auto flow2 =
      distributed->flowVelocity(probes, LoadDensity::constantOverElements(loads), u2.velocities.data(), flow);
  const auto flow1 =
      reference->flowVelocity(probes, LoadDensity::constantOverElements(loads), u1.velocities.data(), flow);
  double scale = 0.0, nodes = 0.0, points = 0.0;
  for (std::size_t k = 0; k < u1.velocities.size(); ++k) {
    scale = std::max(scale, std::abs(u1.velocities[k]));
    nodes = std::max(nodes, std::abs(u1.velocities[k] - u2.velocities[k]));
  }
  for (std::size_t k = 0; k < flow1.size(); ++k) {
    points = std::max(points, std::abs(flow1[k] - flow2[k]));
  }
  if (comm->getRank() == 0) {
    std::printf("%s, lambda %g: 1 vs 2 ranks, node velocities %.2e, flow %.2e of %.3f\n", kernel.c_str(), lambda, nodes,
                points, scale);
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, nodes < 1e-9 * scale)) << nodes;
  EXPECT_TRUE(capsula::testing::allRanks(*comm, points < 1e-9 * scale)) << points;
}

TEST(PeriodicRanks, ExplicitVelocitiesMatchOneRank)
{
  compareRanks("Periodic", false, 1.0);
}

TEST(PeriodicRanks, GmresVelocitiesMatchOneRank)
{
  compareRanks("Periodic", false, 4.0);
}

TEST(PeriodicRanks, AboveTheWallVelocitiesMatchOneRank)
{
  compareRanks("PeriodicWall", true, 1.0);
}

// The channel 0 < y < 3: the ellipsoid's top and two probes lie in its upper half, where the
// upper wall's kernel corrects the near-singular integrals.
TEST(PeriodicRanks, InTheChannelVelocitiesMatchOneRank)
{
  compareRanks("PeriodicChannel", true, 1.0, 3.0);
}

} // namespace
