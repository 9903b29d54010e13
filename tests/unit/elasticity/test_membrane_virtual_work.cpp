// The virtual-work membrane load (MembraneForceMethod::VirtualWork): the nodal forces are
// the exact gradient of the strain energy, carry no net force or torque, reproduce
// Laplace's law on an inflated sphere with mesh convergence, and agree with the thesis's
// contour-integral load where both are accurate.
#include "MembraneTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/elasticity/NeoHookeanLaw.hpp>
#include <capsula/elasticity/SkalakLaw.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace membrane_virtual_work_test { // the file's own names, apart from those of the files compiled with it
namespace {

using namespace capsula::elasticity;
using capsula::elasticity::testing::mapNodes;
using capsula::elasticity::testing::smoothDeformation;
using capsula::mesh::SurfaceMesh;
using capsula::mesh::Vec3;
using capsula::testing::orderOverLevels;

constexpr double G = 0.7;
constexpr double C = 2.5;

std::vector<std::shared_ptr<const MembraneLaw>> laws()
{
  return {std::make_shared<NeoHookeanLaw>(G), std::make_shared<SkalakLaw>(G, C)};
}

MembraneDiscretisation virtualWork()
{
  MembraneDiscretisation d;
  d.forceMethod = MembraneForceMethod::VirtualWork;
  return d;
}

} // namespace

TEST(MembraneVirtualWork, NodalForcesAreTheEnergyGradient)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(1, 1.0);
  const std::vector<double> x = mapNodes(mesh.positions(), smoothDeformation);
  for (const auto& law : laws()) {
    MembraneMechanics m(mesh, mesh.positions(), law, virtualWork());
    m.evaluate(x.data());
    double scale = 0.0, worst = 0.0;
    for (const Vec3& F : m.nodalForces()) {
      scale = std::max(scale, F.norm());
    }
    // Central differences of strainEnergy (the same rule and material coordinates):
    // truncation ~h^2 E''' ~ 1e-10 relative, round-off ~eps E / h ~ 1e-10.
    const double h = 1e-5;
    for (int node = 0; node < mesh.numNodes(); node += 7) {
      for (int d = 0; d < 3; ++d) {
        std::vector<double> plus = x, minus = x;
        plus[3 * node + d] += h;
        minus[3 * node + d] -= h;
        const double slope = (m.strainEnergy(plus.data()) - m.strainEnergy(minus.data())) / (2.0 * h);
        worst = std::max(worst, std::abs(slope - m.nodalForces()[node][d]));
      }
    }
    EXPECT_LT(worst, 1e-8 * scale) << law->name();
  }
}

TEST(MembraneVirtualWork, NoNetForceOrTorque)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const std::vector<double> x = mapNodes(mesh.positions(), smoothDeformation);
  for (const auto& law : laws()) {
    MembraneMechanics m(mesh, mesh.positions(), law, virtualWork());
    m.evaluate(x.data());
    Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
    double scale = 0.0;
    for (int k = 0; k < mesh.numNodes(); ++k) {
      const Vec3& F = m.nodalForces()[k];
      force += F;
      torque += capsula::mesh::nodeAt(x.data(), k).cross(F);
      scale = std::max(scale, F.norm());
    }
    // E is invariant under translation and rotation of all nodes: exact up to round-off
    // in sums over ~650 nodes.
    EXPECT_LT(force.norm(), 1e-12 * scale) << law->name();
    EXPECT_LT(torque.norm(), 1e-12 * scale) << law->name();
    // The continuous load integrates to the same total (1^T M f = 1^T F): the mass solve's
    // residual is 1e-13 relative.
    EXPECT_LT(m.netForce().norm(), 1e-10 * scale) << law->name();
  }
}

TEST(MembraneVirtualWork, ReferenceStateCarriesNoLoad)
{
  const SurfaceMesh mesh = capsula::mesh::makeBiconcaveCell(2);
  for (const auto& law : laws()) {
    MembraneMechanics m(mesh, mesh.positions(), law, virtualWork());
    m.evaluate(mesh.positionData());
    double worst = 0.0;
    for (const Vec3& f : m.nodalLoads()) {
      worst = std::max(worst, f.norm());
    }
    // dw/dI vanish at I1 = I2 = 0 only in combination (dw/dI1 + dw/dI2 = 0 for these
    // laws at rest): the forces cancel to round-off, G = 0.7 sets the scale.
    EXPECT_LT(worst, 1e-12) << law->name();
  }
}

TEST(MembraneVirtualWork, LaplaceLawOnAnInflatedSphereConverges)
{
  // Uniform dilation s of the unit sphere: the isotropic tension T (see
  // test_membrane_sphere.cpp) gives Delta f = (2 T / s) n (ERRATA sign).
  const double s = 1.1;
  for (const auto& law : laws()) {
    const double T = law->name() == "NeoHookean" ? G * (1.0 - std::pow(s, -6.0))
                                                 : G * ((s * s - 1.0) + C * s * s * (std::pow(s, 4.0) - 1.0));
    const double exact = 2.0 * T / s;
    std::vector<int> levels;
    std::vector<double> errors;
    for (int level = 1; level <= 3; ++level) {
      const SurfaceMesh mesh = capsula::mesh::makeSphere(level, 1.0);
      const std::vector<double> x = mapNodes(mesh.positions(), [s](const Vec3& X) { return s * X; });
      MembraneMechanics m(mesh, mesh.positions(), law, virtualWork());
      m.evaluate(x.data());
      double worst = 0.0;
      for (int k = 0; k < mesh.numNodes(); ++k) {
        const Vec3 n = mesh.position(k).normalized();
        worst = std::max(worst, (m.nodalLoads()[k] - exact * n).norm());
      }
      levels.push_back(level);
      errors.push_back(worst / exact);
      std::printf("%s level %d: max |f - 2T/r n| / (2T/r) = %.3e\n", law->name().c_str(), level, worst / exact);
    }
    // The load is the L2 projection of a second-derivative quantity of a quadratic
    // surface: first order in h at the nodes at least.
    EXPECT_GT(orderOverLevels(levels, errors), 0.9) << law->name();
    EXPECT_LT(errors.back(), 0.05) << law->name();
  }
}

TEST(MembraneVirtualWork, AgreesWithTheContourIntegralOnASmoothDeformation)
{
  // Element-averaged loads of the two methods on the same smooth deformation: both
  // approximate -div_s T, so their difference shrinks under refinement.
  std::vector<int> levels;
  std::vector<double> differences;
  const auto law = std::make_shared<SkalakLaw>(G, C);
  for (int level = 1; level <= 3; ++level) {
    const SurfaceMesh mesh = capsula::mesh::makeSphere(level, 1.0);
    const std::vector<double> x = mapNodes(mesh.positions(), smoothDeformation);
    MembraneMechanics work(mesh, mesh.positions(), law, virtualWork());
    MembraneMechanics contour(mesh, mesh.positions(), law);
    work.evaluate(x.data());
    contour.evaluate(x.data());
    double numerator = 0.0, denominator = 0.0;
    for (int e = 0; e < mesh.numElements(); ++e) {
      const double A = work.elementAreas()[e];
      numerator += A * (work.elementLoads()[e] - contour.elementLoads()[e]).squaredNorm();
      denominator += A * contour.elementLoads()[e].squaredNorm();
    }
    levels.push_back(level);
    differences.push_back(std::sqrt(numerator / denominator));
    std::printf("level %d: relative L2 difference of element loads %.3e\n", level, differences.back());
  }
  EXPECT_GT(orderOverLevels(levels, differences), 0.9);
  EXPECT_LT(differences.back(), 0.05);
}

TEST(MembraneVirtualWork, ElementNodeLayoutIsWhatTheSingleLayerIntegrates)
{
  // 18 numbers per element: the continuous load's nodal values (virtual work), or the
  // element's constant load at each of its six nodes (contour integral). Copies: exact.
  const SurfaceMesh mesh = capsula::mesh::makeSphere(1, 1.0);
  const std::vector<double> x = mapNodes(mesh.positions(), smoothDeformation);
  const auto law = std::make_shared<SkalakLaw>(G, C);
  MembraneMechanics work(mesh, mesh.positions(), law, virtualWork());
  MembraneMechanics contour(mesh, mesh.positions(), law);
  work.evaluate(x.data());
  contour.evaluate(x.data());
  std::vector<double> a(18 * static_cast<std::size_t>(mesh.numElements())), b(a.size());
  work.writeElementNodeLoads(a.data());
  contour.writeElementNodeLoads(b.data());
  for (int e = 0; e < mesh.numElements(); ++e) {
    for (int k = 0; k < 6; ++k) {
      for (int d = 0; d < 3; ++d) {
        EXPECT_EQ(a[18 * e + 3 * k + d], work.nodalLoads()[mesh.element(e)[k]][d]);
        EXPECT_EQ(b[18 * e + 3 * k + d], contour.elementLoads()[e][d]);
      }
    }
  }
}

// A right-hand side evaluates the virtual-work membrane with LoadOnly (no nodal average of
// the deformation gradient, no nodal tensions): the load is the full evaluation's, bit for
// bit, the nodal tensions keep the last full evaluation's values, and a fold is still
// caught.
TEST(MembraneVirtualWork, LoadOnlyEvaluationGivesTheSameLoad)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const std::vector<double> x = mapNodes(mesh.positions(), smoothDeformation);
  for (const auto& law : laws()) {
    MembraneMechanics full(mesh, mesh.positions(), law, virtualWork());
    MembraneMechanics light(mesh, mesh.positions(), law, virtualWork());
    full.evaluate(x.data());
    light.evaluate(mesh.positions().data()); // a full evaluation at rest: tensions ~1e-15
    const double atRest = light.nodalPrincipalTensions()[0].major;
    light.evaluate(x.data(), MembraneEvaluation::LoadOnly);
    std::vector<double> a(18 * static_cast<std::size_t>(mesh.numElements())), b(a.size());
    full.writeElementNodeLoads(a.data());
    light.writeElementNodeLoads(b.data());
    EXPECT_EQ(a, b) << law->name();
    EXPECT_EQ(light.nodalPrincipalTensions()[0].major, atRest) << law->name(); // not recomputed
    EXPECT_GT(std::abs(full.nodalPrincipalTensions()[0].major), 1e-3) << law->name();

    // Turn one node's star inside out: the load-only path still stops on the fold.
    std::vector<double> folded = x;
    for (int d = 0; d < 3; ++d) {
      folded[static_cast<std::size_t>(d)] *= -0.2;
    }
    EXPECT_THROW(light.evaluate(folded.data(), MembraneEvaluation::LoadOnly), capsula::core::NumericalError)
        << law->name();
  }
}

// requireUnfolded is evaluate()'s fold check alone: silent where evaluate succeeds, the same
// message where it throws (the same node, element and product), and the membrane's state
// of the last evaluate() untouched.
TEST(MembraneVirtualWork, FoldCheckAloneMatchesEvaluate)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const std::vector<double> x = mapNodes(mesh.positions(), smoothDeformation);
  std::vector<double> folded = x;
  for (int d = 0; d < 3; ++d) {
    folded[static_cast<std::size_t>(d)] *= -0.2;
  }
  for (const auto& law : laws()) {
    MembraneMechanics membrane(mesh, mesh.positions(), law, virtualWork());
    membrane.evaluate(x.data());
    const std::vector<Vec3> loads = membrane.nodalLoads();
    EXPECT_NO_THROW(membrane.requireUnfolded(x.data())) << law->name();
    std::string alone, full;
    try {
      membrane.requireUnfolded(folded.data());
    } catch (const capsula::core::NumericalError& e) {
      alone = e.what();
    }
    EXPECT_EQ(membrane.nodalLoads(), loads) << law->name(); // no member changed
    try {
      membrane.evaluate(folded.data(), MembraneEvaluation::LoadOnly);
    } catch (const capsula::core::NumericalError& e) {
      full = e.what();
    }
    EXPECT_NE(alone.find("the membrane is folded at node "), std::string::npos) << alone;
    EXPECT_EQ(alone, full) << law->name();
  }
}

} // namespace membrane_virtual_work_test
