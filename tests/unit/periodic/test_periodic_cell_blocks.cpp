// The cell-block preconditioner ('Solver/Preconditioner' = "Cell blocks") in the periodic
// channel. Its blocks take the nearest-image kernel of the corrections, not the Ewald sums
// of the operator (LayerPotentials::cellDoubleLayerBlock): they miss each cell's interaction
// with its own periodic images, which flexible GMRES then carries. The solve must still be
// the same equation's.
#include "OperatorTesting.hpp"
#include "PeriodicTesting.hpp"

#include "capsula/testing/VectorDifference.hpp"

#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <cstdio>

namespace {

using namespace capsula;
namespace pt = capsula::periodic::testing;
namespace ot = capsula::operators::testing;

operators::VelocitySolution solveInTheChannel(bool cellBlocks)
{
  // Two level-1 ellipsoids at viscosity ratio 5 (Ewald sums to 1e-8) in a box 2.4 x 2.4 of a channel of height 2.5: each is
  // 0.5-0.9 from its own images across the periods, 0.3 from a wall, 0.5 from the other.
  std::vector<mesh::SurfaceMesh> cells;
  cells.push_back(mesh::makeEllipsoid(1, mesh::Vec3(0.8, 0.4, 0.7), {mesh::Vec3(0.6, 0.7, 0.6)}));
  mesh::Placement turned{mesh::Vec3(1.6, 1.7, 1.7)};
  turned.rotation = mesh::rotationAboutAxis(mesh::Vec3(0.2, 1.0, 0.3), 0.9);
  cells.push_back(mesh::makeEllipsoid(1, mesh::Vec3(0.7, 0.4, 0.6), turned));
  Teuchos::ParameterList settings;
  settings.set("Tolerance", 1e-8);
  operators::SolverParameters parameters;
  parameters.tolerance = 1e-10;
  parameters.cellBlockPreconditioner = cellBlocks;
  auto solver = pt::periodicRegistry().create("PeriodicChannel", ot::serialComm(),
                                              operators::CellSurfaces(std::move(cells), {5.0, 5.0}), {}, parameters,
                                              settings, pt::channel(2.4, 2.4, 2.5));
  const auto loads = ot::elementAverages(solver->surfaces(), [](const mesh::Vec3& x, const mesh::Vec3& n) {
    return mesh::Vec3((1.0 + 0.5 * x[0]) * n + mesh::Vec3(0.2, -0.1, 0.3 * x[1]));
  });
  operators::FlowConditions flow; // shear between the walls
  flow.capillaryNumber = 0.2;
  return solver->nodeVelocities(operators::LoadDensity::constantOverElements(loads), flow);
}

TEST(PeriodicCellBlocks, SolveTheSameEquationWithTheImagesLeftToGmres)
{
  const auto plain = solveInTheChannel(false);
  const auto preconditioned = solveInTheChannel(true);
  const double difference = capsula::testing::relativeDifference(plain.velocities, preconditioned.velocities);
  std::printf("periodic channel: GMRES %d iterations, with cell blocks %d; velocities differ by %.1e relative\n",
              plain.iterations, preconditioned.iterations, difference);
  // Both to 1e-10 on the relative residual of a well-conditioned equation (condition ~5).
  EXPECT_LT(difference, 2e-9);
  EXPECT_LE(preconditioned.residual, 1e-10);
  EXPECT_LE(preconditioned.iterations, 0.65 * plain.iterations);
}

} // namespace
