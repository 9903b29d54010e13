// The flow off the surfaces (eq 3.59) and the wall shear stress (eqs 3.60-3.63).
//
// Hadamard-Rybczynski drop (test_velocity.cpp, docs/operators.md), centre c, radius a,
// x' = x - c, r = |x'|:
//   outside  u = A (U / r + (U.x') x' / r^3) + B (U / r^3 - 3 (U.x') x' / r^5),
//            A = a (2 + 3 lambda) / (4 (1 + lambda)),  B = a^3 lambda / (4 (1 + lambda));
//   inside   u = c0 U + c1 (2 r^2 U - (U.x') x'),
//            c0 = (3 + 2 lambda) / (2 (1 + lambda)),  c1 = -1 / (2 a^2 (1 + lambda)).
// Inside, eq 3.59 gives lambda u; the solver divides by lambda where the cell's solid angle
// says the point is inside.
#include "OperatorTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/greens/Wall3D.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/WallShearStress.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace flow_test { // the file's own names, apart from those of the files compiled with it
namespace {

using namespace capsula;
using namespace capsula::operators;
using capsula::operators::testing::elementAverages;
using capsula::operators::testing::makeSolver;
using capsula::operators::testing::reportConvergence;
using mesh::Vec3;

const Vec3 centre(0.3, -0.2, 0.1);
const double radius = 0.8;
const Vec3 U(0.6, -0.3, 0.8);

Vec3 hadamardRybczynskiFlow(const Vec3& x, double lambda)
{
  const Vec3 d = x - centre;
  const double r = d.norm();
  if (r >= radius) {
    const double A = radius * (2.0 + 3.0 * lambda) / (4.0 * (1.0 + lambda));
    const double B = std::pow(radius, 3) * lambda / (4.0 * (1.0 + lambda));
    return A * (U / r + U.dot(d) * d / std::pow(r, 3)) + B * (U / std::pow(r, 3) - 3.0 * U.dot(d) * d / std::pow(r, 5));
  }
  const double c0 = (3.0 + 2.0 * lambda) / (2.0 * (1.0 + lambda));
  const double c1 = -1.0 / (2.0 * radius * radius * (1.0 + lambda));
  return c0 * U + c1 * (2.0 * r * r * U - U.dot(d) * d);
}

TEST(FlowVelocity, HadamardRybczynskiFlowInsideAndOutside)
{
  const std::vector<Vec3> probes = {centre + Vec3(1.2, 0.1, -0.2), centre + Vec3(-0.3, 2.1, 0.4),
                                    centre + Vec3(0.2, -0.1, 0.3), centre + Vec3(-0.25, 0.2, -0.3)};
  std::vector<double> points;
  for (const Vec3& p : probes) {
    points.insert(points.end(), {p[0], p[1], p[2]});
  }
  for (const double lambda : {0.2, 5.0}) {
    std::vector<int> levels = {1, 2};
    std::vector<double> errors;
    for (const int level : levels) {
      mesh::Placement placement;
      placement.centre = centre;
      auto solver = makeSolver("FreeSpace", mesh::makeSphere(level, radius, placement), lambda);
      const double strength = -3.0 * (2.0 + 3.0 * lambda) / (2.0 * radius * (1.0 + lambda));
      const auto loads = elementAverages(solver->surfaces(), [&](const Vec3& x, const Vec3&) {
        const Vec3 n = (x - centre).normalized();
        return Vec3(strength * U.dot(n) * n);
      });
      FlowConditions flow;
      flow.capillaryNumber = 1.0;
      flow.background = LinearFlow::quiescent();
      const auto nodes = solver->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
      const auto u =
          solver->flowVelocity(points, LoadDensity::constantOverElements(loads), nodes.velocities.data(), flow);
      double error = 0.0;
      for (std::size_t p = 0; p < probes.size(); ++p) {
        const Vec3 exact = hadamardRybczynskiFlow(probes[p], lambda);
        for (int i = 0; i < 3; ++i) {
          error = std::max(error, std::abs(u[3 * p + i] - exact[i]) / U.norm());
        }
      }
      errors.push_back(error);
      const auto omega = solver->solidAnglesAt(points);
      // The regular rule's error on the solid angle (~1e-5 at level 2) is far below the
      // 2 pi that separates inside from outside.
      EXPECT_NEAR(omega[0], 0.0, 1e-4);        // outside
      EXPECT_NEAR(omega[2], 4.0 * M_PI, 1e-4); // inside
    }
    const double order = reportConvergence("HR flow at probes, lambda = " + std::to_string(lambda), levels, errors);
    // The node velocities' O(h^2) load-averaging error carries over (test_velocity).
    EXPECT_LT(errors.back(), 1.5e-2) << "lambda = " << lambda;
    EXPECT_GT(order, 1.8) << "lambda = " << lambda;
  }
}

// Nodes of a passive cell (lambda = 1, no load: it adds nothing to the flow) right next to
// a rigid sphere translating in free space, whose flow is Stokes's (HR with lambda -> oo:
// A = 3a/4, B = a^3/4) and is exactly the single layer of the uniform traction
// f = -3 U / (2a) (the element average of a constant is exact, so only the quadrature errs).
// The passive cell's nodes are targets near elements they do not belong to.
double passiveNeighbourError(double gap, const DiscretisationParameters& parameters)
{
  mesh::Placement a, b;
  a.centre = centre;
  const double small = 0.3;
  b.centre = centre + (radius + gap + small) * Vec3(0.6, 0.0, 0.8);
  auto solver =
      makeSolver("FreeSpace", {mesh::makeSphere(2, radius, a), mesh::makeSphere(2, small, b)}, {1.0, 1.0}, parameters);
  const int numElementsA = solver->surfaces().cell(0).numElements();
  std::vector<double> loads(3 * solver->surfaces().numElements(), 0.0);
  for (int m = 0; m < numElementsA; ++m) {
    for (int i = 0; i < 3; ++i) {
      loads[3 * m + i] = -1.5 / radius * U[i];
    }
  }
  FlowConditions flow;
  flow.capillaryNumber = 1.0;
  flow.background = LinearFlow::quiescent();
  const auto u = solver->nodeVelocities(LoadDensity::constantOverElements(loads), flow).velocities;
  const auto x = solver->surfaces().positions();
  double error = 0.0;
  for (int n = solver->surfaces().nodeOffset(1); n < solver->surfaces().numNodes(); ++n) {
    const Vec3 exact = hadamardRybczynskiFlow(mesh::nodeAt(x.data(), n), 1e12);
    for (int i = 0; i < 3; ++i) {
      error = std::max(error, std::abs(u[3 * n + i] - exact[i]) / U.norm());
    }
  }
  return error;
}

TEST(FlowVelocity, NodesOfAnotherCellNearASurface)
{
  // Level-2 elements of the sphere are ~0.25 long: gaps of 1/12 and 1/50 of an element.
  DiscretisationParameters off;
  off.nearSingularDistance = 0.0;
  for (const double gap : {0.02, 0.005}) {
    const double treated = passiveNeighbourError(gap, DiscretisationParameters{});
    const double untreated = passiveNeighbourError(gap, off);
    std::printf("passive cell %.3f from a Stokes sphere: node velocity error %.2e (near-singular "
                "subdivision) vs %.2e (N_Q rule only)\n",
                gap, treated, untreated);
    // With the subdivision the error is the sphere's own discretisation error (5e-5 at
    // level 2, whatever the gap); without it the regular rule fails near the surface.
    EXPECT_LT(treated, 2e-4) << "gap " << gap;
    EXPECT_GT(untreated, 10.0 * treated) << "gap " << gap;
  }
}

mesh::SurfaceMesh cellAboveWall(int level, double size, double height)
{
  mesh::Placement placement;
  placement.centre = Vec3(0.2, height, -0.1);
  return mesh::makeSphere(level, size, placement);
}

TEST(FlowVelocity, BlakeFlowVanishesOnTheWall)
{
  // Every term of eq 3.59 vanishes at y = 0: u_inf = (y, 0, 0), and the wall Stokeslet
  // and stresslet with the pole on the wall (h = 0) equal their images. The cell is 0.05
  // from the wall, so the wall points below it are within near-singular reach.
  for (const double lambda : {1.0, 5.0}) {
    auto solver = makeSolver("Wall", cellAboveWall(2, 0.8, 0.85), lambda);
    const auto loads = elementAverages(solver->surfaces(), [](const Vec3& x, const Vec3& n) {
      return Vec3((1.0 + 0.5 * x[0]) * n + Vec3(0.2, 0.1, -0.3));
    });
    FlowConditions flow;
    flow.capillaryNumber = 0.3;
    const auto nodes = solver->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
    std::vector<double> wall, above;
    for (const double x : {-2.0, 0.0, 0.2, 0.5, 3.0}) {
      for (const double z : {-1.0, -0.1, 0.3}) {
        wall.insert(wall.end(), {x, 0.0, z});
        above.insert(above.end(), {x, 0.5, z});
      }
    }
    const auto onWall =
        solver->flowVelocity(wall, LoadDensity::constantOverElements(loads), nodes.velocities.data(), flow);
    const auto nearWall =
        solver->flowVelocity(above, LoadDensity::constantOverElements(loads), nodes.velocities.data(), flow);
    const double scale = std::abs(*std::max_element(nearWall.begin(), nearWall.end(),
                                                    [](double a, double b) { return std::abs(a) < std::abs(b); }));
    for (const double v : onWall) {
      // Round-off: the Stokeslet and its image cancel term by term.
      EXPECT_LE(std::abs(v), 1e-12 * scale) << "lambda = " << lambda;
    }
  }
}

// The velocity at x0 of a uniform load of total F on a sphere of radius a centred at c:
// u_j = -1/(8 pi) F_i [G_ij(c, x0) + (a^2 / 6) lap_c G_ij(c, x0)], exact outside the sphere
// (the mean over a sphere of a biharmonic function, as every part of G^W is in c there).
// Its wall gradient d u_j / d x0_y at x0_y = 0, by Richardson from heights 1e-4 and 2e-4
// (u vanishes on the wall, so (4 u(d) - u(2d)) / (2d) errs by O(d^2)); the Laplacian by
// central differences of step 1e-2 (its O(step^2) error is scaled by a^2 / 6).
Vec3 blakeSphereWallGradient(const Vec3& c, double a, const Vec3& F, double px, double pz)
{
  const auto velocity = [&](double h) {
    const double x0[3] = {px, h, pz};
    const auto G = [&](const Vec3& source, int i, int j) {
      double g[3][3];
      greens::Wall3D::stokeslet(source.data(), x0, g);
      return g[i][j];
    };
    const double step = 1e-2;
    Vec3 u = Vec3::Zero();
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 3; ++i) {
        double laplacian = 0.0;
        for (int k = 0; k < 3; ++k) {
          const Vec3 e = step * Vec3::Unit(k);
          laplacian += (G(c + e, i, j) - 2.0 * G(c, i, j) + G(c - e, i, j)) / (step * step);
        }
        u[j] -= F[i] * (G(c, i, j) + a * a / 6.0 * laplacian) / (8.0 * M_PI);
      }
    }
    return u;
  };
  const double d = 1e-4;
  return (4.0 * velocity(d) - velocity(2.0 * d)) / (2.0 * d);
}

TEST(WallShearStress, LoadedSphereMatchesBlakeSolution)
{
  // A sphere of radius 0.2 at height 1 with a uniform load of total F in shear flow,
  // lambda = 1: its velocity field is known in closed form outside it (above), so the wall
  // shear stress is too, independently of the operators' quadratures.
  const double a = 0.2;
  const Vec3 c(0.2, 1.0, -0.1);
  const Vec3 F(1.0, 0.4, -0.6);
  auto solver = makeSolver("Wall", cellAboveWall(3, a, c[1]));
  const Vec3 f = F / (4.0 * M_PI * a * a);
  const auto loads = elementAverages(solver->surfaces(), [&](const Vec3&, const Vec3&) { return f; });
  FlowConditions flow;
  flow.capillaryNumber = 1.0;
  const auto nodes = solver->nodeVelocities(LoadDensity::constantOverElements(loads), flow);
  const std::vector<double> wallPoints = {0.2, -0.1, 1.0, 0.5, -0.7, -1.2, 2.5, 0.0};
  const auto stress = wallShearStress(*solver, wallPoints, 0.02, LoadDensity::constantOverElements(loads),
                                      nodes.velocities.data(), flow);
  double largest = 0.0, error = 0.0;
  for (std::size_t p = 0; p < wallPoints.size() / 2; ++p) {
    const Vec3 du = blakeSphereWallGradient(c, a, F, wallPoints[2 * p], wallPoints[2 * p + 1]);
    const double dudy = 1.0 + du[0]; // the shear u_inf = (y, 0, 0) adds 1
    const double dwdy = du[2];
    largest = std::max({largest, std::abs(du[0]), std::abs(du[2])});
    error = std::max({error, std::abs(stress.dudy[p] - dudy), std::abs(stress.dwdy[p] - dwdy)});
    std::printf("wall point (%.1f, %.1f): du/dy %.7f (exact %.7f)  dw/dy %.7f (exact %.7f)\n", wallPoints[2 * p],
                wallPoints[2 * p + 1], stress.dudy[p], dudy, stress.dwdy[p], dwdy);
    EXPECT_NEAR(stress.magnitude[p], std::hypot(stress.dudy[p], stress.dwdy[p]), 1e-15);
  }
  std::printf("largest disturbance gradient on the wall %.3e, largest error %.3e\n", largest, error);
  EXPECT_GT(largest, 0.01); // the disturbance is not negligible: the test has teeth
  // The stencil's O(step^4) error (measured 2e-4 of the largest gradient at step 0.02,
  // 2e-3 at step 0.04) and the level-3 quadrature: 1e-3 of the largest disturbance gradient.
  EXPECT_LT(error, 1e-3 * largest);
}

TEST(WallShearStress, UndisturbedShearGivesOne)
{
  // No load, lambda = 1: the cell follows the shear and the wall sees mu k, i.e. 1.
  auto solver = makeSolver("Wall", cellAboveWall(1, 0.5, 1.0));
  const std::vector<double> zero(3 * solver->surfaces().numElements(), 0.0);
  FlowConditions flow;
  const auto nodes = solver->nodeVelocities(LoadDensity::constantOverElements(zero), flow);
  const auto stress = wallShearStress(*solver, {0.0, 0.0, 1.0, 2.0}, 0.05, LoadDensity::constantOverElements(zero),
                                      nodes.velocities.data(), flow);
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_NEAR(stress.magnitude[p], 1.0, 1e-13); // the stencil is exact for linear u
    EXPECT_NEAR(stress.dwdy[p], 0.0, 1e-13);
  }
  EXPECT_THROW(
      wallShearStress(*solver, {0.0, 0.0}, 0.0, LoadDensity::constantOverElements(zero), nodes.velocities.data(), flow),
      core::InputError);
}

} // namespace

} // namespace flow_test
