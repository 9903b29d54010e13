// The membrane's tangent stiffness H = d2E/dx dx (MembraneEnergyHessian.hpp,
// MembraneMechanics::tangentStiffness): the laws' second derivatives, H against
// differences of the virtual-work nodal forces, symmetry, the rigid motions, and
// positive semi-definiteness at rest.
#include "MembraneTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/elasticity/NeoHookeanLaw.hpp>
#include <capsula/elasticity/SkalakLaw.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace membrane_tangent_stiffness_test { // the file's own names, apart from those of the files compiled with it
namespace {

using namespace capsula::elasticity;
using capsula::elasticity::testing::mapNodes;
using capsula::elasticity::testing::smoothDeformation;
using capsula::mesh::SurfaceMesh;
using capsula::mesh::Vec3;

constexpr double G = 0.7;

std::vector<std::shared_ptr<const MembraneLaw>> laws()
{
  return {std::make_shared<NeoHookeanLaw>(G), std::make_shared<SkalakLaw>(G, 2.5),
          std::make_shared<SkalakLaw>(G, 10.0)};
}

MembraneDiscretisation virtualWork()
{
  MembraneDiscretisation d;
  d.forceMethod = MembraneForceMethod::VirtualWork;
  return d;
}

// A direction with every node moving differently (smooth and grid-scale parts).
std::vector<double> testDirection(std::size_t n)
{
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = std::sin(1.3 * static_cast<double>(i) + 0.2) + 0.3 * std::cos(0.11 * static_cast<double>(i));
  }
  return v;
}

std::vector<double> nodalForces(MembraneMechanics& m, const std::vector<double>& x)
{
  m.evaluate(x.data(), MembraneEvaluation::LoadOnly);
  std::vector<double> F;
  for (const Vec3& f : m.nodalForces()) {
    F.insert(F.end(), {f[0], f[1], f[2]});
  }
  return F;
}

double maxAbs(const std::vector<double>& v)
{
  double m = 0.0;
  for (const double x : v) {
    m = std::max(m, std::abs(x));
  }
  return m;
}

} // namespace

// d2w/dI dI against central differences of the first derivatives (the laws are
// polynomial or rational in I2: truncation ~1e-10 at step 1e-5).
TEST(MembraneTangentStiffness, LawSecondDerivatives)
{
  for (const auto& law : laws()) {
    for (const auto& [I1, I2] : {std::pair{0.0, 0.0}, std::pair{0.3, -0.2}, std::pair{-0.1, 0.6}}) {
      const double h = 1e-5;
      const auto d = law->energySecondDerivatives(I1, I2);
      const auto p1 = law->energyDerivatives(I1 + h, I2), m1 = law->energyDerivatives(I1 - h, I2);
      const auto p2 = law->energyDerivatives(I1, I2 + h), m2 = law->energyDerivatives(I1, I2 - h);
      EXPECT_NEAR(d.dI1dI1, (p1.dI1 - m1.dI1) / (2 * h), 1e-8) << law->name();
      EXPECT_NEAR(d.dI1dI2, (p2.dI1 - m2.dI1) / (2 * h), 1e-8) << law->name();
      EXPECT_NEAR(d.dI1dI2, (p1.dI2 - m1.dI2) / (2 * h), 1e-8) << law->name();
      EXPECT_NEAR(d.dI2dI2, (p2.dI2 - m2.dI2) / (2 * h), 1e-8) << law->name();
    }
  }
}

// H v is the derivative of the nodal forces F = dE/dx in the direction v, on a deformed
// level-2 sphere with tension and compression. Central differences at 1e-6: truncation
// ~1e-12 relative, round-off ~1e-16 / 1e-6 = 1e-10 relative to |F|; a wrong factor in
// any term of H shows as an O(1) error.
TEST(MembraneTangentStiffness, IsTheDerivativeOfTheNodalForces)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const std::vector<double> x = mapNodes(mesh.positions(), smoothDeformation);
  const std::vector<double> v = testDirection(x.size());
  for (const auto& law : laws()) {
    MembraneMechanics m(mesh, mesh.positions(), law, virtualWork());
    const TangentStiffness H = m.tangentStiffness(x.data());
    std::vector<double> Hv(x.size());
    H.apply(v.data(), Hv.data());
    const double eps = 1e-6;
    std::vector<double> plus(x), minus(x);
    for (std::size_t i = 0; i < x.size(); ++i) {
      plus[i] += eps * v[i];
      minus[i] -= eps * v[i];
    }
    const std::vector<double> Fp = nodalForces(m, plus), Fm = nodalForces(m, minus);
    double worst = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      worst = std::max(worst, std::abs(Hv[i] - (Fp[i] - Fm[i]) / (2 * eps)));
    }
    EXPECT_LT(worst, 1e-7 * maxAbs(Hv)) << law->name();
  }
}

// Symmetric (a second derivative), translations in the kernel, and a rotation omega x x
// maps to omega x F (E(R x) = E(x), so F(R x) = R F(x); differentiate at R = I).
TEST(MembraneTangentStiffness, SymmetryAndRigidMotions)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(1, 1.0);
  const std::vector<double> x = mapNodes(mesh.positions(), smoothDeformation);
  const std::size_t n = x.size();
  for (const auto& law : laws()) {
    MembraneMechanics m(mesh, mesh.positions(), law, virtualWork());
    const TangentStiffness H = m.tangentStiffness(x.data());
    std::vector<double> dense(n * n, 0.0);
    H.forEachEntry([&](int r, int c, double value) { dense[static_cast<std::size_t>(r) * n + c] += value; });
    double scale = maxAbs(dense), asymmetry = 0.0;
    for (std::size_t r = 0; r < n; ++r) {
      for (std::size_t c = 0; c < r; ++c) {
        asymmetry = std::max(asymmetry, std::abs(dense[r * n + c] - dense[c * n + r]));
      }
    }
    EXPECT_LT(asymmetry, 1e-13 * scale) << law->name(); // round-off of the element sums

    const std::vector<double> F = nodalForces(m, x);
    const Vec3 omega(0.3, -0.7, 0.5), shift(1.0, -2.0, 0.5);
    std::vector<double> rotation(n), translation(n), Hr(n), Ht(n);
    for (std::size_t i = 0; i < n; i += 3) {
      const Vec3 r = omega.cross(Vec3(x[i], x[i + 1], x[i + 2]));
      for (int d = 0; d < 3; ++d) {
        rotation[i + d] = r[d];
        translation[i + d] = shift[d];
      }
    }
    H.apply(rotation.data(), Hr.data());
    H.apply(translation.data(), Ht.data());
    double rotationError = 0.0;
    for (std::size_t i = 0; i < n; i += 3) {
      const Vec3 expected = omega.cross(Vec3(F[i], F[i + 1], F[i + 2]));
      for (int d = 0; d < 3; ++d) {
        rotationError = std::max(rotationError, std::abs(Hr[i + d] - expected[d]));
      }
    }
    EXPECT_LT(rotationError, 1e-12 * maxAbs(Hr) + 1e-13 * scale) << law->name();
    EXPECT_LT(maxAbs(Ht), 1e-13 * scale) << law->name();
  }
}

// At rest E is at its minimum: v^T H v >= 0 for every v (checked on grid-scale and
// smooth directions), and E(x + eps v) = eps^2 / 2 v^T H v + O(eps^3).
TEST(MembraneTangentStiffness, PositiveAtRestAndTheEnergysCurvature)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(1, 1.0);
  const std::vector<double> X = mesh.positions();
  for (const auto& law : laws()) {
    MembraneMechanics m(mesh, X, law, virtualWork());
    const TangentStiffness H = m.tangentStiffness(X.data());
    for (int k = 0; k < 5; ++k) {
      std::vector<double> v(X.size()), Hv(X.size());
      for (std::size_t i = 0; i < v.size(); ++i) {
        v[i] = std::sin((0.7 + k) * static_cast<double>(i) + k) * (k % 2 ? 1.0 : X[i]);
      }
      H.apply(v.data(), Hv.data());
      double curvature = 0.0;
      for (std::size_t i = 0; i < v.size(); ++i) {
        curvature += v[i] * Hv[i];
      }
      EXPECT_GT(curvature, 0.0) << law->name() << " direction " << k;
      const double eps = 1e-4;
      std::vector<double> moved(X);
      for (std::size_t i = 0; i < v.size(); ++i) {
        moved[i] += eps * v[i];
      }
      // The cubic term is ~eps^3 |v|^3 E''' : relative 1e-3 at eps = 1e-4 with |v| ~ 10.
      EXPECT_NEAR(m.strainEnergy(moved.data()), 0.5 * eps * eps * curvature, 2e-3 * 0.5 * eps * eps * curvature)
          << law->name() << " direction " << k;
    }
  }
}

// The contour-integral load is not an energy gradient: no tangent stiffness for it.
TEST(MembraneTangentStiffness, RefusedForTheContourIntegralLoad)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(1, 1.0);
  MembraneMechanics m(mesh, mesh.positions(), std::make_shared<NeoHookeanLaw>(G));
  EXPECT_THROW(m.tangentStiffness(mesh.positions().data()), capsula::core::InputError);
}

} // namespace membrane_tangent_stiffness_test
