// Receptors on a curved membrane and their bond forces spread onto the nodes by virtual work:
// total force and torque exactly those of the point forces.
#include <capsula/adhesion/AdhesionOutputs.hpp>
#include <capsula/adhesion/BondPopulation.hpp>
#include <capsula/adhesion/Receptors.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/mesh/Icosphere.hpp>
#include <capsula/mesh/Measures.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace adhesion = capsula::adhesion;
namespace mesh = capsula::mesh;
using mesh::Vec3;

namespace {

// A unit icosphere stretched into an egg and lifted above the wall: curved, without symmetry.
mesh::SurfaceMesh eggAboveWall(int level)
{
  mesh::SurfaceMesh m = mesh::makeIcosphere(level);
  for (int n = 0; n < m.numNodes(); ++n) {
    const Vec3 x = m.position(n);
    m.setPosition(n, Vec3(1.3 * x[0] + 0.2 * x[1] * x[1], x[1] + 1.05, 0.8 * x[2] + 0.3));
  }
  return m;
}

} // namespace

// Point receptors and receptors spread over patches of radius 0.3 (18-30 quadrature points
// each at level 2).
TEST(BondForces, SpreadingKeepsTotalForceAndTorqueToRoundOff)
{
  const mesh::SurfaceMesh egg = eggAboveWall(2);
  const std::vector<double> reference = mesh::makeIcosphere(2).positions();
  for (const double radius : {0.0, 0.3}) {
    adhesion::ReceptorSet receptors(egg, reference, 40.0, 7, 0);
    if (radius > 0.0) {
      receptors.spreadOverPatches(egg, reference, radius, "Adhesion/Patch radius");
    }
    adhesion::AdhesionSettings s;
    adhesion::BondPopulation bonds(s, 0, receptors.size());
    // Every third receptor bonded to an anchor somewhere on the wall: forces of all directions.
    for (int r = 0; r < receptors.size(); r += 3) {
      bonds.setState(r, {1.0, Vec3(0.3 * std::sin(r), 0.0, 0.2 * std::cos(r))});
    }
    // The membrane deformed away from where the receptors were placed (not a rigid motion).
    std::vector<double> x = egg.positions();
    for (std::size_t i = 0; i < x.size(); i += 3) {
      x[i] += 0.05 * std::sin(3.0 * x[i + 1]);
    }
    std::vector<double> nodal(x.size(), 0.0);
    const Vec3 total = bonds.addNodalForces(egg, receptors, x.data(), nodal.data());

    Vec3 pointForce = Vec3::Zero(), pointTorque = Vec3::Zero(), nodalForce = Vec3::Zero(), nodalTorque = Vec3::Zero();
    double scale = 0.0;
    const Vec3 about(0.4, -0.7, 1.1);
    for (int r = 0; r < receptors.size(); ++r) {
      const Vec3 xr = receptors.position(egg, x.data(), r);
      const Vec3 f = bonds.force(r, xr);
      pointForce += f;
      pointTorque += (xr - about).cross(f);
      scale += f.norm() * (1.0 + (xr - about).norm());
    }
    for (int n = 0; n < egg.numNodes(); ++n) {
      const Vec3 f = mesh::nodeAt(nodal.data(), n);
      nodalForce += f;
      nodalTorque += (mesh::nodeAt(x.data(), n) - about).cross(f);
    }
    ASSERT_GT(scale, 1.0); // hundreds of bonds pulling with O(1) forces
    // Round-off: sums of a few thousand products of O(1) numbers, each exact to 1e-16
    // relative: 1e-13 of the sum of magnitudes leaves a margin of ~100, and catches a missing
    // shape function (an error of phi_k ~ 0.1 of a single force) or a patch share.
    EXPECT_LT((nodalForce - pointForce).norm(), 1e-13 * scale) << "radius " << radius;
    EXPECT_LT((nodalTorque - pointTorque).norm(), 1e-13 * scale) << "radius " << radius;
    EXPECT_LT((total - pointForce).norm(), 1e-13 * scale) << "radius " << radius;
  }
}

// A patch on the unit sphere (level 3, reference = current): its weighted mean lies inside
// the sphere by the bump-weighted mean of 1 - cos(r), measured 0.0050 on average for rho =
// 0.2, about rho^2 / 8 (bound: between 0 and rho^2 / 2), and along its point's direction to within 0.2 rho (the
// quadrature points are not symmetric about every receptor). Node shares sum to 1.
TEST(Receptors, PatchIsCentredOnItsPointAndSumsToOne)
{
  const mesh::SurfaceMesh sphere = mesh::makeIcosphere(3);
  const std::vector<double> x = sphere.positions();
  const adhesion::ReceptorSet points(sphere, x, 5.0, 11, 0);
  adhesion::ReceptorSet patches(sphere, x, 5.0, 11, 0);
  const double rho = 0.2;
  patches.spreadOverPatches(sphere, x, rho, "Adhesion/Patch radius");
  ASSERT_TRUE(patches.patched());
  ASSERT_GT(points.size(), 40);
  std::vector<adhesion::NodeWeight> weights;
  double depth = 0.0;
  for (int r = 0; r < points.size(); ++r) {
    const Vec3 p = points.position(sphere, x.data(), r);
    const Vec3 X = patches.position(sphere, x.data(), r);
    depth += (1.0 - X.norm()) / points.size();
    EXPECT_GT(1.0 - X.norm(), 0.0);
    EXPECT_LT(1.0 - X.norm(), 0.5 * rho * rho);
    EXPECT_LT((X.normalized() - p.normalized()).norm(), 0.2 * rho);
    patches.nodeWeights(sphere, r, weights);
    double sum = 0.0;
    for (const auto& w : weights) {
      sum += w.weight;
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
  }
  std::printf("mean depth of a patch's centre below the surface: %.5f (rho^2 / 6 = %.5f)\n", depth, rho * rho / 6);
}

// A radius that holds fewer than three quadrature points is refused, naming the key.
TEST(Receptors, PatchTooSmallForTheMeshIsRefused)
{
  const mesh::SurfaceMesh sphere = mesh::makeIcosphere(1);
  adhesion::ReceptorSet receptors(sphere, sphere.positions(), 5.0, 11, 0);
  try {
    receptors.spreadOverPatches(sphere, sphere.positions(), 0.01, "Adhesion/Patch radius");
    FAIL() << "a patch of 0.01 a on a level-1 mesh was accepted";
  } catch (const capsula::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Adhesion/Patch radius' = 0.01"), std::string::npos) << e.what();
  }
}

TEST(BondForces, StretchedBondPullsTowardsItsAnchor)
{
  const mesh::SurfaceMesh sphere = mesh::makeIcosphere(1);
  const adhesion::ReceptorSet receptors(sphere, sphere.positions(), 10.0, 3, 0);
  adhesion::AdhesionSettings s;
  s.springConstant = 7.0;
  s.equilibriumLength = 0.02;
  adhesion::BondPopulation bonds(s, 0, receptors.size());
  const Vec3 x = receptors.position(sphere, sphere.positions().data(), 0);
  bonds.setState(0, {1.0, x - Vec3(0.0, 0.1, 0.0)}); // anchor 0.1 below: stretched by 0.08
  const Vec3 f = bonds.force(0, x);
  // sigma (L - lambda) = 7 x 0.08 along -y, exactly up to the rounding of 0.1 and 0.02.
  EXPECT_NEAR(f[1], -0.56, 1e-14);
  EXPECT_NEAR(f[0], 0.0, 1e-15);
  bonds.setState(0, {1.0, x - Vec3(0.0, 0.01, 0.0)}); // compressed: pushes off the anchor
  EXPECT_NEAR(bonds.force(0, x)[1], 0.07, 1e-14);
}

TEST(Receptors, CountFollowsDensityAndPointsMoveWithTheMembrane)
{
  const mesh::SurfaceMesh sphere = mesh::makeIcosphere(2);
  const double density = 30.0;
  const adhesion::ReceptorSet receptors(sphere, sphere.positions(), density, 11, 2);
  const double expected = density * mesh::surfaceArea(sphere);
  // Each element rounds its expected count up or down at random: a sum of 1280 Bernoulli
  // variables of variance <= 1/4, standard deviation <= 18; 4 of them bound the count.
  EXPECT_LT(std::abs(receptors.size() - expected), 4.0 * std::sqrt(sphere.numElements() / 4.0));
  // The same seed gives the same receptors; another cell (stream) other ones.
  const adhesion::ReceptorSet again(sphere, sphere.positions(), density, 11, 2);
  const adhesion::ReceptorSet other(sphere, sphere.positions(), density, 11, 3);
  ASSERT_EQ(again.size(), receptors.size());
  EXPECT_EQ(again[17].xi, receptors[17].xi);
  EXPECT_NE(other[17].xi, receptors[17].xi);
  // A rigid translation moves every receptor by the same vector (to round-off of O(1) sums).
  std::vector<double> moved = sphere.positions();
  for (std::size_t i = 0; i < moved.size(); i += 3) {
    moved[i] += 0.5;
    moved[i + 1] += 2.0;
  }
  for (int r = 0; r < receptors.size(); r += 97) {
    const Vec3 d = receptors.position(sphere, moved.data(), r) - receptors.position(sphere, sphere.positionData(), r);
    EXPECT_LT((d - Vec3(0.5, 2.0, 0.0)).norm(), 1e-14);
    // On the sphere's discrete surface: within the chord sag (~1e-3 at level 2) of radius 1.
    EXPECT_NEAR(receptors.position(sphere, sphere.positionData(), r).norm(), 1.0, 2e-3);
  }
}

TEST(AdhesionOutputs, SummaryCountsBondsForceAndContact)
{
  mesh::SurfaceMesh sphere = mesh::makeIcosphere(2);
  std::vector<double> x = sphere.positions();
  double lowest = 1.0;
  for (std::size_t i = 1; i < x.size(); i += 3) {
    lowest = std::min(lowest, x[i]);
  }
  for (std::size_t i = 1; i < x.size(); i += 3) {
    x[i] += 0.01 - lowest; // lowest node 0.01 above the wall
  }
  const adhesion::ReceptorSet receptors(sphere, sphere.positions(), 20.0, 5, 0);
  adhesion::AdhesionSettings s;
  adhesion::BondPopulation bonds(s, 0, receptors.size());
  bonds.setState(4, {1.0, Vec3::Zero()});
  const auto summary = adhesion::summariseAdhesion(bonds, sphere, receptors, x.data());
  EXPECT_EQ(summary.bonds, 1.0);
  EXPECT_LT((summary.bondForce - bonds.force(4, receptors.position(sphere, x.data(), 4))).norm(), 1e-15);
  EXPECT_NEAR(summary.minimumGap, 0.01, 1e-12);
  // The nodes within r_0 = 0.05 of the wall: a cap of height ~0.04, area 2 pi 0.04 ~ 0.25,
  // resolved by the node spacing (~0.15 at level 2): a few node shares of ~0.02.
  EXPECT_GT(summary.contactArea, 0.0);
  EXPECT_LT(summary.contactArea, 0.5);
}
