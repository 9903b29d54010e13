// The stiffness K = -dF/dx of the bond, tether and wall-contact nodal forces
// (LoadStiffness.hpp), what the stiff Jacobian adds to the membrane's tangent stiffness: K x
// against central differences of the nodal forces, for bonds stretched, compressed and of
// every direction on a curved, deformed membrane, a point and a patch tether, and for nodes
// at every height of the repulsion's range.
#include <capsula/adhesion/BondPopulation.hpp>
#include <capsula/adhesion/ContactRepulsion.hpp>
#include <capsula/adhesion/LoadStiffness.hpp>
#include <capsula/adhesion/Receptors.hpp>
#include <capsula/adhesion/Tether.hpp>
#include <capsula/mesh/Icosphere.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace adhesion = capsula::adhesion;
namespace mesh = capsula::mesh;
using mesh::Vec3;

namespace {

std::vector<double> direction(std::size_t n)
{
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = std::sin(1.3 * static_cast<double>(i) + 0.2) + 0.4 * std::cos(0.11 * static_cast<double>(i));
  }
  return v;
}

// max |K v + (F(x + e v) - F(x - e v)) / 2e| over the entries, and max |K v|.
std::pair<double, double> mismatch(const adhesion::LoadStiffness& K, const std::vector<double>& x,
                                   const std::function<void(const double*, double*)>& addForces)
{
  const std::vector<double> v = direction(x.size());
  std::vector<double> Kv(x.size(), 0.0);
  K.addProduct(v.data(), Kv.data());
  const double e = 1e-6;
  std::vector<double> plus(x), minus(x), fp(x.size(), 0.0), fm(x.size(), 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    plus[i] += e * v[i];
    minus[i] -= e * v[i];
  }
  addForces(plus.data(), fp.data());
  addForces(minus.data(), fm.data());
  double worst = 0.0, size = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    worst = std::max(worst, std::abs(Kv[i] + (fp[i] - fm[i]) / (2 * e)));
    size = std::max(size, std::abs(Kv[i]));
  }
  return {worst, size};
}

} // namespace

// Central differences at e = 1e-6 of forces of size ~sigma: truncation ~e^2 |F'''| (the bond
// lengths are >= 0.02, |F'''| ~ sigma / L^2 ~ 1e4 sigma: ~1e-8 sigma), round-off ~1e-16 / e
// ~1e-10: bound 1e-6 of |K v|. A wrong sign is a 200% error, a transposed or missing
// transverse term (1 - lambda/L) an O(1) one.
TEST(LoadStiffness, BondsAreTheDerivativeOfTheirNodalForces)
{
  mesh::SurfaceMesh egg = mesh::makeIcosphere(2);
  const std::vector<double> reference = egg.positions();
  std::vector<double> x = reference;
  for (std::size_t i = 0; i < x.size(); i += 3) {
    const double y = x[i + 1];
    x[i] = 1.3 * x[i] + 0.05 * std::sin(3.0 * y);
    x[i + 1] = y + 1.05;
    x[i + 2] = 0.8 * x[i + 2];
  }
  for (const double radius : {0.0, 0.3}) { // point receptors, and patches (Receptors.hpp)
    adhesion::ReceptorSet receptors(egg, reference, 40.0, 7, 0);
    if (radius > 0.0) {
      receptors.spreadOverPatches(egg, reference, radius, "Adhesion/Patch radius");
    }
    adhesion::AdhesionSettings s;
    s.springConstant = 25.0;
    s.equilibriumLength = 0.3;
    s.kinetics = adhesion::BondKinetics::MeanField; // fractional occupancies weight the bonds
    adhesion::BondPopulation bonds(s, 0, receptors.size());
    int bound = 0;
    std::size_t entries = 0;
    std::vector<adhesion::NodeWeight> weights;
    for (int r = 0; r < receptors.size(); r += 3) {
      // Anchors at distances 0.1-0.5 in all directions: bonds compressed (L < lambda) and stretched.
      const Vec3 p = receptors.position(egg, x.data(), r);
      const Vec3 d(std::sin(r), std::cos(0.7 * r), std::sin(0.3 * r + 1.0));
      bonds.setState(
          r, {0.5 + 0.5 * std::cos(r) * std::cos(r), p - (0.1 + 0.4 * std::abs(std::sin(2.1 * r))) * d.normalized()});
      ++bound;
      receptors.nodeWeights(egg, r, weights);
      entries += 9 * weights.size() * weights.size();
    }
    ASSERT_GT(bound, 20);
    adhesion::LoadStiffness K;
    bonds.addStiffness(egg, receptors, x.data(), K);
    EXPECT_EQ(K.numEntries(), entries); // 18 x 18 per point receptor
    const auto [worst, size] =
        mismatch(K, x, [&](const double* y, double* f) { bonds.addNodalForces(egg, receptors, y, f); });
    EXPECT_GT(size, 1.0);
    EXPECT_LT(worst, 1e-6 * size) << worst << " of " << size << ", radius " << radius;
  }
}

// The wall repulsion, both loads: 'Virtual work' K_kl = -int phi_k phi_l p'(y) dS, 'Nodal
// area' -p'(y_k) a_k on the diagonal. Symmetric, on the wall-normal coordinate only, positive
// semi-definite (p' <= 0), and exact for a rigid vertical shift, which changes no area and no
// shape: K e_y = -dF/dh. Differences at e = 1e-6 of a pressure whose third derivative is
// ~p_0 / delta^3 ~ 1e5 p_0 at the smallest gap 0.004 (~delta / 12): truncation ~1e-7 of
// |K v|, bound 1e-5. A general displacement also changes the areas and shapes K leaves out
// (terms of the size of the force, not of its derivative).
TEST(LoadStiffness, WallContactIsTheDerivativeOfItsNodalForces)
{
  const mesh::SurfaceMesh sphere = mesh::makeIcosphere(3);
  std::vector<double> x = sphere.positions();
  for (std::size_t i = 1; i < x.size(); i += 3) {
    x[i] += 1.004; // lowest node 0.004 above the wall, a ring of elements within the range
  }
  for (const auto load : {adhesion::ContactLoad::NodalArea, adhesion::ContactLoad::VirtualWork}) {
    adhesion::ContactSettings contact;
    contact.enabled = true;
    contact.range = 0.05;
    contact.strength = 10.0;
    contact.load = load;
    adhesion::LoadStiffness K;
    adhesion::addWallContactStiffness(contact, sphere, x.data(), K);
    ASSERT_GT(K.numEntries(), 3u);
    std::vector<double> dense(x.size() * x.size(), 0.0);
    K.forEachEntry([&](int row, int column, double value) {
      EXPECT_EQ(row % 3, 1); // the wall-normal coordinate only
      EXPECT_EQ(column % 3, 1);
      if (load == adhesion::ContactLoad::NodalArea) {
        EXPECT_EQ(row, column);
      }
      dense[static_cast<std::size_t>(row) * x.size() + static_cast<std::size_t>(column)] += value;
    });
    double largest = 0.0;
    for (double v : dense) {
      largest = std::max(largest, std::abs(v));
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        EXPECT_NEAR(dense[i * x.size() + j], dense[j * x.size() + i], 1e-14 * largest);
      }
    }
    const std::vector<double> v = direction(x.size());
    std::vector<double> Kv(x.size(), 0.0);
    K.addProduct(v.data(), Kv.data());
    double vKv = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      vKv += v[i] * Kv[i];
    }
    EXPECT_GT(vKv, 0.0); // a restoring stiffness: the repulsion weakens with the gap
    // The rigid shift.
    std::vector<double> shift(x.size(), 0.0);
    for (std::size_t i = 1; i < x.size(); i += 3) {
      shift[i] = 1.0;
    }
    std::vector<double> Ks(x.size(), 0.0);
    K.addProduct(shift.data(), Ks.data());
    const double e = 1e-6;
    std::vector<double> plus(x), minus(x), fp(x.size(), 0.0), fm(x.size(), 0.0);
    for (std::size_t i = 1; i < x.size(); i += 3) {
      plus[i] += e;
      minus[i] -= e;
    }
    adhesion::addWallContactForces(contact, sphere, plus.data(), fp.data());
    adhesion::addWallContactForces(contact, sphere, minus.data(), fm.data());
    double worst = 0.0, size = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      worst = std::max(worst, std::abs(Ks[i] + (fp[i] - fm[i]) / (2 * e)));
      size = std::max(size, std::abs(Ks[i]));
    }
    EXPECT_LT(worst, 1e-5 * size) << worst << " of " << size;
  }
}

// p'(d) against differences of p(d) across the range, and 0 at and beyond it (C1 there).
TEST(LoadStiffness, PressureSlopeIsTheDerivativeOfThePressure)
{
  adhesion::ContactSettings contact;
  contact.enabled = true;
  contact.range = 0.05;
  contact.strength = 3.0;
  for (const double d : {0.002, 0.01, 0.025, 0.04, 0.049}) {
    const double e = 1e-7;
    const double difference =
        (adhesion::repulsionPressure(contact, d + e) - adhesion::repulsionPressure(contact, d - e)) / (2 * e);
    const double slope = adhesion::repulsionPressureSlope(contact, d);
    EXPECT_LT(slope, 0.0) << d;
    EXPECT_NEAR(slope, difference, 1e-6 * std::abs(slope) + 1e-6) << d;
  }
  EXPECT_EQ(adhesion::repulsionPressureSlope(contact, 0.05), 0.0);
  EXPECT_EQ(adhesion::repulsionPressureSlope(contact, 0.2), 0.0);
}

// The tether pulls at the weighted mean X of its points, so every node of the patch is
// coupled to every other (c_k c_l): a patch whose nodes were coupled only within an element
// would miss most entries. Stretched (L > lambda) and compressed to an anchor off to the side
// on a deformed egg; differences at e = 1e-6 of F(X) with |F'''| ~ sigma / L^2 (L ~ 0.5):
// truncation ~1e-12 sigma, bound 1e-6 of |K v| as for the bonds.
TEST(LoadStiffness, TetherIsTheDerivativeOfItsNodalForces)
{
  mesh::SurfaceMesh egg = mesh::makeIcosphere(2);
  const std::vector<double> reference = egg.positions();
  for (int n = 0; n < egg.numNodes(); ++n) {
    const Vec3 p = egg.position(n);
    egg.setPosition(n, Vec3(1.3 * p[0] + 0.1 * p[1], p[1] + 1.2, 0.8 * p[2]));
  }
  std::vector<double> x = egg.positions();
  for (std::size_t i = 0; i < x.size(); i += 3) {
    x[i] += 0.05 * std::sin(3.0 * x[i + 1]);
  }
  for (const double radius : {0.0, 0.3}) {
    for (const double restLength : {0.05, 1.0}) {
      adhesion::TetherSettings s;
      s.enabled = true;
      s.patchRadius = radius;
      s.anchor = Vec3(0.4, 0.0, -0.2);
      s.restLength = restLength;
      s.springConstant = 30.0;
      const adhesion::Tether tether(s, egg, egg.positionData(), reference);
      adhesion::LoadStiffness K;
      tether.addStiffness(egg, x.data(), K);
      const auto [worst, size] = mismatch(K, x, [&](const double* y, double* f) { tether.addNodalForces(egg, y, f); });
      EXPECT_GT(size, 0.1) << radius; // not empty: sigma = 30 spread over the patch's nodes
      EXPECT_LT(worst, 1e-6 * size) << "patch " << radius << ", rest length " << restLength << ": " << worst << " of "
                                    << size;
    }
  }
}
