// The periodic double layers (the spectral Ewald stresslet sums of the periodic fluid, the
// periodic wall and the periodic channel, each minus the own cell's subtraction term with its
// local kernel) against the identity they rest on: for a constant density c and a
// node x0 of cell A, PV int_A T n dS c = -4 pi c and int_B T n dS c = 0 for another closed
// surface B (docs/extending.md), so the subtracted double layer at every node is -4 pi c
// up to the quadrature's error, as for FreeSpace (Wall). A wrong sign of the Ewald sum leaves
// +8 pi c - 4 pi c; a subtraction with the wrong kernel leaves the images' flux.
#include "PeriodicTesting.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace capsula;
namespace pt = capsula::periodic::testing;

double largestIdentityError(const std::string& kernel, const domain::Domain& domain,
                            const std::vector<mesh::Vec3>& centres)
{
  std::vector<mesh::SurfaceMesh> cells;
  for (const auto& centre : centres) {
    cells.push_back(mesh::makeEllipsoid(2, mesh::Vec3(0.6, 0.45, 0.5), {centre}));
  }
  auto solver = pt::makeSolver(kernel, std::move(cells), std::vector<double>(centres.size(), 2.0), domain, 1e-9);
  const double c[3] = {0.3, -1.0, 0.7};
  std::vector<double> density;
  for (int n = 0; n < solver->surfaces().numNodes(); ++n) {
    density.insert(density.end(), c, c + 3);
  }
  const std::vector<double> dl = solver->doubleLayer(density.data(), operators::DoubleLayerForm::Subtracted);
  double error = 0.0;
  for (std::size_t k = 0; k < dl.size(); ++k) {
    error = std::max(error, std::abs(dl[k] + 4.0 * M_PI * c[k % 3]));
  }
  return error;
}

TEST(PeriodicDoubleLayer, ConstantDensityGivesMinusFourPiAcrossTheBoundary)
{
  // Two cells 0.15 apart across the boundary x = L_x of a box 2.6 x 2.4, each within a
  // period of its own images (a cell is 1.2 long).
  const std::vector<mesh::Vec3> across = {mesh::Vec3(2.15, 1.0, 1.2), mesh::Vec3(3.5 - 2.6, 1.1, 1.3)};
  const std::vector<mesh::Vec3> apart = {mesh::Vec3(2.15, 1.0, 1.2), mesh::Vec3(3.5, 1.1, 1.3)};
  const double periodic = largestIdentityError("Periodic", pt::box(2.6, 2.4, false), across);
  const double free = largestIdentityError("FreeSpace", domain::Domain::unbounded(), apart);
  std::printf("constant density: largest |DL + 4 pi c|, Periodic %.3e, FreeSpace (same pair) %.3e\n", periodic, free);
  // FreeSpace's error is the N_Q rule's on the near cells (level 2); the periodic one adds
  // the images' flux through the cells, integrated by the same rule, and the Ewald error
  // (1e-9 of the largest value): twice FreeSpace's plus 1e-6 bounds it. Either sign error
  // gives an error of order 4 pi |c| = 15.
  EXPECT_LT(periodic, 2.0 * free + 1e-6);
}

TEST(PeriodicDoubleLayer, ConstantDensityGivesMinusFourPiAboveThePeriodicWallAndInTheChannel)
{
  // The same pair across the boundary, one cell 0.1 above the lower wall (its half-height is
  // 0.45), the other 0.7 above it. Blake's kernel ("Wall") on the pair placed apart bounds the
  // quadrature's error; the wall's images add their flux through the cells, integrated by the
  // same rule. In the channel H = 2.4 the second cell lies 0.15 below the upper wall, whose
  // nodes take that wall's kernel in the subtraction. Measured 2.3e-7 for both against Wall's
  // 1.1e-7; bound twice Wall's plus 1e-6. The free-space kernel in the wall's subtraction
  // errs by 6.0e-3, the lower wall's kernel in the channel's by 4.0e-4: both fail.
  const std::vector<mesh::Vec3> across = {mesh::Vec3(2.15, 0.55, 1.2), mesh::Vec3(3.5 - 2.6, 1.8, 1.3)};
  const std::vector<mesh::Vec3> apart = {mesh::Vec3(2.15, 0.55, 1.2), mesh::Vec3(3.5, 1.8, 1.3)};
  const double wall = largestIdentityError("Wall", domain::Domain::aboveWall(), apart);
  const double periodicWall = largestIdentityError("PeriodicWall", pt::box(2.6, 2.4, true), across);
  const double channel = largestIdentityError("PeriodicChannel", pt::channel(2.6, 2.4, 2.4), across);
  std::printf("constant density: largest |DL + 4 pi c|, PeriodicWall %.3e, PeriodicChannel %.3e, Wall (same pair) "
              "%.3e\n",
              periodicWall, channel, wall);
  EXPECT_LT(periodicWall, 2.0 * wall + 1e-6);
  EXPECT_LT(channel, 2.0 * wall + 1e-6);
}

} // namespace
