// The cell-block preconditioner of the viscosity-ratio equation (CellBlockPreconditioner.hpp)
// and the block it inverts, LayerPotentials::cellDoubleLayerBlock.
#include "OperatorTesting.hpp"

#include "capsula/testing/VectorDifference.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/operators/BuiltInKernels.hpp>
#include <capsula/operators/CellBlockPreconditioner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using namespace capsula;
using namespace capsula::operators;
using mesh::Vec3;
namespace ot = capsula::operators::testing;

// Three cells above the wall: a sphere, an ellipsoid turned out of every axis, a small
// sphere. At spread 1 they are close enough to couple strongly (gaps of 0.3-0.5 radii between
// them, 0.3 to the wall); `spread` scales the centres' coordinates.
CellSurfaces crowdAboveTheWall(double lambdaSmall, double spread = 1.0)
{
  mesh::Placement a, b, c;
  a.centre = spread * Vec3(0.0, 1.3, 0.0);
  b.centre = spread * Vec3(2.2, 1.1, 0.4);
  b.rotation = mesh::rotationAboutAxis(Vec3(0.3, 0.2, 1.0), 0.7);
  c.centre = spread * Vec3(1.0, 1.2, 1.75);
  return CellSurfaces(
      {mesh::makeSphere(2, 1.0, a), mesh::makeEllipsoid(2, Vec3(1.0, 0.5, 0.8), b), mesh::makeSphere(1, 0.6, c)},
      {5.0, 5.0, lambdaSmall});
}

// A density with every kind of mode: rigid motions, a stretch and a swirl.
std::vector<double> smoothDensity(const CellSurfaces& surfaces)
{
  return ot::nodalField(surfaces, [](const Vec3& x) {
    return Vec3(0.3 + 0.5 * x[1] - 0.2 * x[2] * x[2], -0.4 + 0.7 * x[0] * x[2], 0.1 + std::sin(x[0]) - 0.3 * x[1]);
  });
}

std::vector<double> elementLoads(const CellSurfaces& surfaces)
{
  return ot::elementAverages(
      surfaces, [](const Vec3& x, const Vec3& n) { return Vec3((2.0 + x[0]) * n + Vec3(0.3, -0.2, 0.1 * x[2])); });
}

using capsula::testing::relativeDifference;

// max |block u_c - DL[u_c]| / max |DL[u_c]| over the rows of each cell c, u_c the density
// on cell c and 0 elsewhere.
template <class Kernel>
double worstBlockMismatch(const CellSurfaces& surfaces)
{
  KernelBoundaryIntegralSolver<Kernel> solver(ot::serialComm(), surfaces, DiscretisationParameters{},
                                              SolverParameters{});
  const std::vector<double> density = smoothDensity(surfaces);
  double worst = 0.0;
  std::vector<double> block;
  for (int c = 0; c < surfaces.numCells(); ++c) {
    const int first = surfaces.nodeOffset(c);
    const int n = (c + 1 < surfaces.numCells() ? surfaces.nodeOffset(c + 1) : surfaces.numNodes()) - first;
    std::vector<double> own(density.size(), 0.0);
    std::copy(density.begin() + 3 * first, density.begin() + 3 * (first + n), own.begin() + 3 * first);
    const std::vector<double> full = solver.doubleLayer(own.data(), DoubleLayerForm::Subtracted);
    EXPECT_EQ(solver.layerPotentials().cellDoubleLayerBlock(c, block), n);
    std::vector<double> product(3 * static_cast<std::size_t>(n), 0.0), reference(product.size());
    for (int r = 0; r < 3 * n; ++r) {
      for (int k = 0; k < 3 * n; ++k) {
        product[r] += block[static_cast<std::size_t>(r) * 3 * n + k] * own[3 * first + k];
      }
      reference[r] = full[3 * first + r];
    }
    worst = std::max(worst, relativeDifference(reference, product));
  }
  return worst;
}

TEST(CellBlockPreconditioner, CellBlockIsTheDoubleLayerOfTheCellsOwnDensity)
{
  // With the direct sums the regular rule of the block and of the operator are the same
  // sums, so the block times the cell's density is the double layer of that density alone,
  // to round-off (sums of ~1e3 terms of size ~10): a wrong sign or a missing term (the
  // subtraction, -4 pi u, a correction) is O(1). Both built-in kernels; the wall's images
  // are part of the block.
  const CellSurfaces surfaces = crowdAboveTheWall(1.0);
  const double freeSpace = worstBlockMismatch<FreeSpace3DKernel>(surfaces);
  const double wall = worstBlockMismatch<Wall3DKernel>(surfaces);
  std::printf("cell block x own density vs the double layer: free space %.2e, wall %.2e\n", freeSpace, wall);
  EXPECT_LT(freeSpace, 1e-12);
  EXPECT_LT(wall, 1e-12);
}

// Solves the crowd's equation with and without the preconditioner (tolerance 1e-10).
void solveBothWays(double lambdaSmall, double spread, VelocitySolution& plain, VelocitySolution& preconditioned)
{
  SolverParameters parameters;
  parameters.tolerance = 1e-10;
  const CellSurfaces surfaces = crowdAboveTheWall(lambdaSmall, spread);
  std::vector<mesh::SurfaceMesh> cells;
  for (int c = 0; c < surfaces.numCells(); ++c) {
    cells.push_back(surfaces.cell(c));
  }
  std::vector<double> lambdas = {5.0, 5.0, lambdaSmall};
  auto a = ot::makeSolver("Wall", cells, lambdas, {}, parameters);
  parameters.cellBlockPreconditioner = true;
  auto b = ot::makeSolver("Wall", cells, lambdas, {}, parameters);
  const auto loads = elementLoads(surfaces);
  FlowConditions flow; // shear over the wall
  flow.capillaryNumber = 0.2;
  plain = a->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  preconditioned = b->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
}

TEST(CellBlockPreconditioner, SolvesTheSameEquationInFewerIterations)
{
  // Spread 3: the cells are apart and their own blocks hold nearly all of A; spread 1: the
  // crowd, where the near field between neighbours is left to GMRES. Measured (tolerance
  // 1e-10): 14-16 iterations against 4 apart, 17-20 against 10-11 in the crowd.
  for (const double spread : {3.0, 1.0}) {
    for (const double lambdaSmall : {0.2, 1.0}) { // 1: an identity block beside two others
      VelocitySolution plain, preconditioned;
      solveBothWays(lambdaSmall, spread, plain, preconditioned);
      const double difference = relativeDifference(plain.velocities, preconditioned.velocities);
      std::printf("spread %.0f, lambda (5, 5, %.1f): GMRES %d iterations, with cell blocks %d (residual %.1e); "
                  "velocities differ by %.1e\n",
                  spread, lambdaSmall, plain.iterations, preconditioned.iterations, preconditioned.residual,
                  difference);
      // Both solved to 1e-10 on ||b - A u|| / ||b||; A's condition number is ~5 (eigenvalues
      // 1/3 to 5/3 at lambda = 5), so the velocities agree to a few 1e-10.
      EXPECT_LT(difference, 2e-9);
      EXPECT_LE(preconditioned.residual, 1e-10);
      if (spread > 1.0) {
        // The blocks invert A but for the weak coupling and the LU's single precision: each
        // iteration gains about three digits.
        EXPECT_LE(preconditioned.iterations, 4);
        EXPECT_GE(plain.iterations, 12);
      } else {
        EXPECT_LE(preconditioned.iterations, 0.65 * plain.iterations);
      }
    }
  }
}

} // namespace

namespace {

// PreconditionerRefresh::OnRequest (a time integration's, scene::Scene::startStep): a solve
// after a move keeps the blocks of the first geometry and still solves the moved geometry's
// equation; after refreshPreconditioner() the blocks, and so the solve, are those of a
// solver built at the moved geometry, bit for bit.
TEST(CellBlockPreconditioner, StaleBlocksSolveTheMovedEquationAndARefreshRebuildsThem)
{
  const CellSurfaces surfaces = crowdAboveTheWall(0.2);
  std::vector<mesh::SurfaceMesh> cells;
  for (int c = 0; c < surfaces.numCells(); ++c) {
    cells.push_back(surfaces.cell(c));
  }
  const std::vector<double> lambdas = {5.0, 5.0, 0.2};
  SolverParameters parameters;
  parameters.tolerance = 1e-10;
  parameters.cellBlockPreconditioner = true;
  auto fresh = ot::makeSolver("Wall", cells, lambdas, {}, parameters);
  parameters.preconditionerRefresh = SolverParameters::PreconditionerRefresh::OnRequest;
  auto kept = ot::makeSolver("Wall", cells, lambdas, {}, parameters);
  const auto loads = LoadDensity::constantOverElements(elementLoads(surfaces));
  FlowConditions flow;
  flow.capillaryNumber = 0.2;
  const auto first = kept->nodeVelocities(loads, flow);
  // A step's worth of motion: the nodes move by 5% of the first velocities.
  std::vector<double> moved = surfaces.positions();
  for (std::size_t k = 0; k < moved.size(); ++k) {
    moved[k] += 0.05 * first.velocities[k];
  }
  fresh->setPositions(moved.data());
  kept->setPositions(moved.data());
  const auto rebuilt = fresh->nodeVelocities(loads, flow);
  const auto stale = kept->nodeVelocities(loads, flow);
  const double difference = relativeDifference(rebuilt.velocities, stale.velocities);
  std::printf("moved cells: rebuilt blocks %d iterations, stale blocks %d; velocities differ by %.1e\n",
              rebuilt.iterations, stale.iterations, difference);
  EXPECT_LT(difference, 2e-9); // both to 1e-10, as in SolvesTheSameEquationInFewerIterations
  EXPECT_LE(stale.iterations, rebuilt.iterations + 2);
  EXPECT_NE(stale.velocities, rebuilt.velocities); // the stale blocks did steer another way
  kept->refreshPreconditioner();
  EXPECT_EQ(kept->nodeVelocities(loads, flow).velocities, rebuilt.velocities);
}

} // namespace

namespace {

// The preconditioner on its own, over two cells of 2 nodes (6 unknowns each) whose blocks
// the test chooses: D_00 a fixed well-conditioned matrix, D_11 = I / s_1, so that P_1 = 0.
Teuchos::RCP<const Tpetra::Map<>> serialMap(int numNodes)
{
  return Teuchos::rcp(new Tpetra::Map<>(3 * numNodes, 0, ot::serialComm()));
}

double chosenEntry(int r, int k)
{
  return (r == k ? 2.0 : 0.0) + 0.1 * std::sin(1.0 + r + 2.0 * k);
}

TEST(CellBlockPreconditioner, AppliesTheInverseOfEachCellsBlock)
{
  const double s = 0.25;
  CellBlockPreconditioner M(serialMap(4), {0, 2, 4}, {s, 0.0}, [](int cell, std::vector<double>& rows) {
    EXPECT_EQ(cell, 0) << "a cell of scale 0 has the identity and no block";
    rows.resize(36);
    for (int r = 0; r < 6; ++r) {
      for (int k = 0; k < 6; ++k) {
        rows[6 * r + k] = chosenEntry(r, k);
      }
    }
    return 2;
  });
  EXPECT_EQ(M.heldBlocks(), 1);
  Tpetra::MultiVector<double> x(M.getDomainMap(), 1), y(M.getRangeMap(), 1);
  {
    auto data = x.getDataNonConst(0);
    for (int k = 0; k < 12; ++k) {
      data[k] = std::cos(0.7 * k);
    }
  }
  M.apply(x, y);
  // P_0 y_0 = x_0 with P_0 = I - s D_00; the second cell's rows pass through.
  const auto in = x.getData(0);
  const auto out = y.getData(0);
  for (int r = 0; r < 6; ++r) {
    double Py = out[r];
    for (int k = 0; k < 6; ++k) {
      Py -= s * chosenEntry(r, k) * out[k];
    }
    EXPECT_NEAR(Py, in[r], 1e-6) << r; // single-precision LU of a matrix of condition ~2
  }
  for (int r = 6; r < 12; ++r) {
    EXPECT_EQ(out[r], in[r]) << r;
  }
}

TEST(CellBlockPreconditioner, RefusesASingularBlockNamingTheCell)
{
  const double s = 0.25;
  try {
    CellBlockPreconditioner M(serialMap(4), {0, 2, 4}, {s, s}, [s](int cell, std::vector<double>& rows) {
      rows.assign(36, 0.0);
      for (int r = 0; r < 6; ++r) {
        rows[6 * r + r] = cell == 1 ? 1.0 / s : 1.0;
      }
      return 2;
    });
    ADD_FAILURE() << "a singular block was factorised";
  } catch (const core::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("block of cell 1 is singular"), std::string::npos) << e.what();
  }
}

} // namespace
