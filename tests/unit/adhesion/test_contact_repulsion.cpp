// The contact repulsion: its profile, a rigid sphere driven onto the wall, and two cells
// pressed together.
#include <capsula/adhesion/ContactRepulsion.hpp>
#include <capsula/mesh/Icosphere.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace adhesion = capsula::adhesion;
namespace mesh = capsula::mesh;
using mesh::Vec3;

namespace {

adhesion::ContactSettings contactSettings()
{
  adhesion::ContactSettings c;
  c.enabled = true;
  c.range = 0.05;
  c.strength = 10.0;
  return c;
}

// Sphere positions with the lowest node at height `gap`.
std::vector<double> sphereAtGap(const mesh::SurfaceMesh& sphere, double gap)
{
  std::vector<double> x = sphere.positions();
  double lowest = 0.0;
  for (std::size_t i = 1; i < x.size(); i += 3) {
    lowest = std::min(lowest, x[i]);
  }
  for (std::size_t i = 1; i < x.size(); i += 3) {
    x[i] += gap - lowest;
  }
  return x;
}

} // namespace

TEST(ContactRepulsion, ZeroBeyondRangeMonotoneAndDivergingAtContact)
{
  const auto c = contactSettings();
  EXPECT_EQ(adhesion::repulsionPressure(c, c.range), 0.0);
  EXPECT_EQ(adhesion::repulsionPressure(c, 2.0 * c.range), 0.0);
  double previous = std::numeric_limits<double>::infinity();
  for (int i = 1; i < 1000; ++i) {
    const double p = adhesion::repulsionPressure(c, c.range * i / 1000.0);
    ASSERT_GT(p, 0.0) << i;
    ASSERT_LT(p, previous) << i; // strictly decreasing
    previous = p;
  }
  // C1 at the range: p(delta - e) = O(e^2) (p''(delta) e^2 / 2, p'' ~ p_0 g''(1) / delta^2).
  const double e = 1e-4 * c.range;
  EXPECT_LT(adhesion::repulsionPressure(c, c.range - e), 2.0 * c.strength * 1e-8);
  // At small gaps p = p_0 (delta / d - 1/2 - g(1) + g'(1)) + p_0 s (1/12 - g'(1)) + O(s^3),
  // s = d / delta (g(s) = 1/s - 1/2 + s/12 - ...): at s = 1e-4 the remainder is 1.0e-4 p_0,
  // and a wrong shift (the 2.0027) would be off by O(p_0).
  const double d = 1e-4 * c.range;
  const double shift = 0.5 + 1.0 / (std::exp(1.0) - 1.0) + std::exp(1.0) / std::pow(std::exp(1.0) - 1.0, 2);
  EXPECT_NEAR(adhesion::repulsionPressure(c, d), c.strength * (c.range / d - shift), 2e-4 * c.strength);
}

TEST(ContactRepulsion, StopsARigidSphereDrivenOntoTheWall)
{
  // A rigid unit sphere pushed down by a constant force P, with Stokes mobility 1/(6 pi):
  // dh/dt = (F_wall(h) - P) / (6 pi), RK4 with the step limited to 0.5 / (the local
  // relaxation rate mobility x dF/dh) and to 10% of the gap per step, as an adaptive
  // integrator's error control would limit it. The
  // repulsion must hold the sphere above the wall and bring it to rest where F_wall = P.
  const auto c = contactSettings();
  const mesh::SurfaceMesh sphere = mesh::makeIcosphere(2);
  const std::vector<double> areas = adhesion::nodalAreaShares(sphere, sphere.positionData());
  const auto wallForce = [&](double gap) {
    const std::vector<double> x = sphereAtGap(sphere, gap);
    std::vector<double> f(x.size(), 0.0);
    return adhesion::addWallContactForces(c, sphere, x.data(), areas, f.data())[1];
  };
  const double mobility = 1.0 / (6.0 * 3.14159265358979323846);
  const auto relaxationRate = [&](double gap) {
    const double h = 1e-3 * gap;
    return mobility * (wallForce(gap - h) - wallForce(gap + h)) / (2.0 * h);
  };
  for (const double load : {2.0, 20.0, 200.0}) {
    const auto rate = [&](double gap) { return mobility * (wallForce(gap) - load); };
    double gap = 0.2, smallest = gap;
    int steps = 0;
    for (double t = 0.0; t < 40.0 && std::abs(wallForce(gap) - load) > 1e-8 * load; ++steps) {
      const double dt = std::min({1e-2, 0.5 / std::max(relaxationRate(gap), 1e-12), 0.1 * gap / std::abs(rate(gap))});
      const double k1 = rate(gap), k2 = rate(gap + 0.5 * dt * k1), k3 = rate(gap + 0.5 * dt * k2),
                   k4 = rate(gap + dt * k3);
      gap += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      t += dt;
      smallest = std::min(smallest, gap);
    }
    std::printf("load %g G a: rest gap %.5f a (smallest %.5f) after %d steps, relaxation rate %.3g\n", load, gap,
                smallest, steps, relaxationRate(gap));
    EXPECT_GT(smallest, 0.0);
    // At rest: the repulsion balances the load (the loop stops at 1e-8 of it, or after 40
    // time units, hundreds of relaxation times of every load here).
    EXPECT_NEAR(wallForce(gap), load, 1e-6 * load);
  }
}

TEST(ContactRepulsion, CellsPressedTogetherFeelEqualAndOppositeForces)
{
  const auto c = contactSettings();
  const mesh::SurfaceMesh a = mesh::makeIcosphere(2);
  const mesh::SurfaceMesh b = mesh::makeIcosphere(2);
  const std::vector<double> areas = adhesion::nodalAreaShares(a, a.positionData());
  for (const double separation : {2.02, 2.2}) {
    std::vector<double> xa = a.positions(), xb = b.positions();
    for (std::size_t i = 0; i < xb.size(); i += 3) {
      xb[i] += separation;
      xb[i + 1] += 0.013; // off the symmetry line: forces with a torque arm
    }
    std::vector<double> fa(xa.size(), 0.0), fb(xb.size(), 0.0);
    const Vec3 onA = adhesion::addCellContactForces(c, a, xa.data(), areas, fa.data(), b, xb.data(), areas, fb.data());
    Vec3 totalA = Vec3::Zero(), totalB = Vec3::Zero(), torque = Vec3::Zero();
    double scale = 0.0;
    for (int n = 0; n < a.numNodes(); ++n) {
      totalA += mesh::nodeAt(fa.data(), n);
      totalB += mesh::nodeAt(fb.data(), n);
      torque += mesh::nodeAt(xa.data(), n).cross(mesh::nodeAt(fa.data(), n)) +
                mesh::nodeAt(xb.data(), n).cross(mesh::nodeAt(fb.data(), n));
      scale += mesh::nodeAt(fa.data(), n).norm() * 3.0;
    }
    if (separation > 2.0 + c.range + 0.02) {
      EXPECT_EQ(totalA.norm(), 0.0);
      EXPECT_EQ(totalB.norm(), 0.0);
      continue;
    }
    EXPECT_LT(onA[0], 0.0); // A is pushed away from B (B lies along +x)
    // Round-off of sums of ~100 terms of size ~scale / 100.
    EXPECT_LT((totalA - onA).norm(), 1e-13 * scale);
    EXPECT_LT((totalA + totalB).norm(), 1e-13 * scale);
    EXPECT_LT(torque.norm(), 1e-13 * scale);
  }
}
