// Two cells that interact across the periodic boundary move as the same pair placed inside
// the box: the node velocities of both viscosity-ratio paths (single layer only, and the
// double layer's GMRES solve) agree to the Ewald sums' tolerance. The gap (about 0.09 radii,
// a third of an element size) makes the cells near-singular to each other, so a pole whose images in
// the neighbouring boxes were missed, or a cell taken at its unfolded position, would be
// integrated with the regular rule only (errors of 1e-3 and more).
#include "PeriodicTesting.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace capsula;
namespace pt = capsula::periodic::testing;
namespace ot = capsula::operators::testing;

const double lx = 4.0, lz = 3.0;

std::vector<mesh::SurfaceMesh> pair(const mesh::Vec3& first, const mesh::Vec3& second)
{
  std::vector<mesh::SurfaceMesh> cells;
  cells.push_back(mesh::makeSphere(1, 0.5, {first}));
  cells.push_back(mesh::makeEllipsoid(1, mesh::Vec3(0.55, 0.45, 0.5), {second}));
  return cells;
}

// A load that depends on the normal only, so each cell carries the same load wherever it is.
mesh::Vec3 normalLoad(const mesh::Vec3& /*x*/, const mesh::Vec3& n)
{
  return mesh::Vec3(n[0] * (1.0 + 0.5 * n[0]) + 0.2 * n[1], n[1] - 0.3 * n[2], n[2] + 0.4 * n[0] * n[1]);
}

std::vector<double> velocities(const std::string& kernel, std::vector<mesh::SurfaceMesh> cells, double lambda,
                               const domain::Domain& domain)
{
  auto solver = pt::makeSolver(kernel, std::move(cells), {lambda, lambda}, domain, 1e-9);
  const auto load = operators::LoadDensity::constantOverElements(ot::elementAverages(solver->surfaces(), normalLoad));
  operators::FlowConditions flow;
  flow.capillaryNumber = 0.1;
  flow.background = operators::LinearFlow::simpleShear(1.0);
  return solver->nodeVelocities(load, flow).velocities;
}

void expectSameVelocities(const std::string& kernel, double lambda, const domain::Domain& domain)
{
  const mesh::Vec3 first(1.5, 1.0, 1.4), second(2.62, 1.12, 1.55);
  // The same pair moved by (2, 0, 1.4), the first cell by two more periods along x and the
  // second one back by a period along x and z: the centres (11.5, 1, 2.8) and
  // (0.62, 1.12, -0.05) are 11 apart in unfolded coordinates, nearest images across both
  // boundaries, and the first cell straddles z = L_z.
  const mesh::Vec3 shift(2.0, 0.0, 1.4);
  const std::vector<double> inside = velocities(kernel, pair(first, second), lambda, domain);
  const std::vector<double> across = velocities(
      kernel, pair(first + shift + mesh::Vec3(2 * lx, 0, 0), second + shift - mesh::Vec3(lx, 0, lz)), lambda, domain);
  ASSERT_EQ(inside.size(), across.size());
  double difference = 0.0, size = 0.0;
  for (std::size_t k = 0; k < inside.size(); ++k) {
    difference = std::max(difference, std::abs(inside[k] - across[k]));
    size = std::max(size, std::abs(inside[k]));
  }
  std::printf("%s, lambda %g: largest node velocity %.4f, inside vs across %.3e\n", kernel.c_str(), lambda, size,
              difference);
  // The Ewald sums at 1e-9 of the largest velocity see the points at other places of their
  // grid (errors ~1e-10, measured 0.05-0.3 tol), the near-singular corrections the same
  // geometry up to round-off of the shifts, GMRES converged to 1e-12: 1e-8 of the largest
  // velocity bounds them with a margin of 10 or more; missing the near-singular treatment
  // across the boundary costs 1e-3 (the regular rule at a fraction of an element size).
  EXPECT_LT(difference, 1e-8 * size);
}

TEST(PeriodicPair, AcrossTheBoundaryMovesAsInsideTheBox)
{
  expectSameVelocities("Periodic", 1.0, pt::box(lx, lz, false));
}

TEST(PeriodicPair, AcrossTheBoundaryMovesAsInsideTheBoxWithTheDoubleLayer)
{
  expectSameVelocities("Periodic", 5.0, pt::box(lx, lz, false));
}

TEST(PeriodicPair, AboveTheWallAcrossTheBoundaryMovesAsInsideTheBox)
{
  expectSameVelocities("PeriodicWall", 1.0, pt::box(lx, lz, true));
}

// The channel 0 < y < 2.2: the pair (heights 0.5 to 1.57) straddles the mid-plane, so each
// cell's nodes take the lower or the upper wall's kernel by their height.
TEST(PeriodicPair, InTheChannelAcrossTheBoundaryMovesAsInsideTheBox)
{
  expectSameVelocities("PeriodicChannel", 1.0, pt::channel(lx, lz, 2.2));
}

} // namespace
