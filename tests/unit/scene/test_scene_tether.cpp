// A tether in a scene: built only when 'Tether/Enabled' asks for it, its force reaches the
// membrane whole, a stretched tether moves the cell towards its anchor, and the inputs that
// cannot work are refused naming the key.
#include "SceneTestDecks.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/scene/CellKinematics.hpp>
#include <capsula/scene/Scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace {

namespace adhesion = capsula::adhesion;
namespace core = capsula::core;
namespace mesh = capsula::mesh;
namespace scene = capsula::scene;
using scene::testing::makeScene;
using scene::testing::realArray;
using scene::testing::sceneRefusal;
using scene::testing::smallDeck;

// A level-1 sphere 0.05 a above the wall tethered at its lowest point (0, 0.05, 0) to an
// anchor 0.3 a upstream with rest length 0: a stretched tether pulling upstream and down.
void stretchedTether(Teuchos::ParameterList& deck)
{
  auto& tether = deck.sublist("Tether");
  tether.set("Enabled", true);
  tether.set("Spring constant", 20.0);
  tether.set("Anchor", realArray({-0.3, 0.0, 0.0}));
  tether.set("Rest length", realArray({0.0}));
}

TEST(SceneTether, BuiltOnlyWhenEnabled)
{
  for (bool enabled : {false, true}) {
    auto deck =
        smallDeck(1, 1.05, true, [&](Teuchos::ParameterList& d) { d.sublist("Tether").set("Enabled", enabled); });
    auto s = makeScene(*deck);
    EXPECT_EQ(s.hasTether(), enabled);
    EXPECT_FALSE(s.hasBonds());
    EXPECT_EQ(s.externalForces(0) != nullptr, enabled);
    const bool named = std::any_of(s.terms().begin(), s.terms().end(),
                                   [](const std::string& t) { return t.find("tether: Cells/Cell 0") == 0; });
    EXPECT_EQ(named, enabled);
    if (enabled) { // the defaults: below the lowest point, unstressed at the start
      const mesh::Vec3 x = s.tether().attachment(s.cell(0), s.initialPositions().data());
      EXPECT_NEAR(x[1], 0.05, 2e-3);
      EXPECT_EQ(s.tether().anchor()[1], 0.0);
      EXPECT_EQ(s.tether().restLength(), x[1]);
    }
  }
}

TEST(SceneTether, ForceReachesTheMembraneWhole)
{
  // The spread nodal forces sum to the spring's force, and the membrane (unstressed at t = 0,
  // dE/dx = 0 to round-off) passes them to the fluid: its nodal forces F_k = dE/dx_k - f_ext
  // sum to minus them.
  auto deck = smallDeck(1, 1.05, true, stretchedTether);
  auto s = makeScene(*deck);
  const std::vector<double>& x = s.initialPositions();
  std::vector<double> u;
  s.velocity(0.0, x, u);
  const mesh::Vec3 expected = s.tether().state(s.cell(0), x.data()).force;
  ASSERT_GT(expected.norm(), 5.0); // 20 x ~0.3
  const std::vector<double>* external = s.externalForces(0);
  ASSERT_NE(external, nullptr);
  mesh::Vec3 spread = mesh::Vec3::Zero(), membrane = mesh::Vec3::Zero();
  for (int k = 0; k < s.cell(0).numNodes(); ++k) {
    spread += mesh::nodeAt(external->data(), k);
    membrane += s.membrane(0).nodalForces()[static_cast<std::size_t>(k)];
  }
  // Sums of O(10) nodal terms of size |F|: round-off ~1e-15 |F| each.
  EXPECT_LT((spread - expected).norm(), 1e-13 * expected.norm()) << spread.transpose();
  EXPECT_LT((membrane + expected).norm(), 1e-10 * expected.norm()) << membrane.transpose();
}

TEST(SceneTether, StretchedTetherMovesTheCellAtRestTowardsItsAnchor)
{
  // The velocity the tether alone gives the cell: the tethered scene's minus the free one's at
  // the same positions. At lambda = 1 the velocity is linear in the loads, and the membrane
  // is unstressed at the start, so the difference is the motion a stretched tether gives a
  // cell at rest in fluid at rest. It moves the centroid and the attachment point towards the
  // anchor (upstream and down), and not sideways.
  auto tethered = makeScene(*smallDeck(1, 1.05, true, stretchedTether));
  auto free = makeScene(*smallDeck(1, 1.05, true));
  const std::vector<double>& x = tethered.initialPositions();
  std::vector<double> withTether, without;
  tethered.velocity(0.0, x, withTether);
  free.velocity(0.0, x, without);
  std::vector<double> induced(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    induced[i] = withTether[i] - without[i];
  }
  const mesh::Vec3 v = scene::centroidVelocity(tethered.cell(0), induced.data());
  const adhesion::TetherState state = tethered.tether().state(tethered.cell(0), x.data());
  const mesh::Vec3 towards = (state.anchor - state.attachment).normalized();
  EXPECT_GT(v.dot(towards), 0.5 * v.norm()) << v.transpose(); // within 60 degrees of the anchor's direction
  EXPECT_LT(v[0], 0.0);                                       // upstream
  EXPECT_LT(std::abs(v[2]), 1e-10 * v.norm());                // the xy plane is a mirror plane
  // The attachment point moves towards the anchor too, faster than the centroid (the
  // membrane gives way under the point load).
  std::vector<double> moved = x;
  const double dt = 1e-6;
  for (std::size_t i = 0; i < x.size(); ++i) {
    moved[i] += dt * induced[i];
  }
  const mesh::Vec3 w = (tethered.tether().attachment(tethered.cell(0), moved.data()) - state.attachment) / dt;
  EXPECT_GT(w.dot(towards), 0.0);
  EXPECT_GT(w.dot(towards), v.dot(towards));
}

TEST(SceneTether, RefusesInputsThatCannotWork)
{
  const auto enable = [](Teuchos::ParameterList& d) -> Teuchos::ParameterList& {
    d.sublist("Tether").set("Enabled", true);
    return d.sublist("Tether");
  };
  EXPECT_NE(sceneRefusal([&](auto& d) { enable(d); }, false)
                .find("'Tether/Enabled' is true but 'Wall/Enabled' "
                      "is false"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) { enable(d).set("Cell", 1); }).find("'Tether/Cell' = 1 but the scene has 1"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) {
              enable(d).set("Anchor", realArray({0.0, -0.1, 0.0}));
            }).find("'Tether/Anchor' = {0, -0.1, 0} lies off the wall"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) { enable(d).set("Spring constant", 0.0); }).find("'Tether/Spring constant'"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) {
              enable(d);
              d.sublist("Cells").sublist("Cell 0").set("Membrane forces", "Contour integral");
            }).find("'Tether/Enabled' is true but 'Cells/Cell 0/Membrane forces'"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) {
              enable(d);
              d.sublist("Mesh adaption").set("Enabled", true);
            }).find("'Mesh adaption/Enabled'"),
            std::string::npos);
  // The tether and the receptor-ligand bonds together: both forces reach the membrane.
  EXPECT_EQ(sceneRefusal([&](auto& d) {
              enable(d);
              d.sublist("Adhesion").set("Enabled", true);
            }),
            "");
}

TEST(SceneTether, BondsAndTetherAddUp)
{
  // With adhesion on and a bond set by hand, the external forces are the bond's plus the
  // tether's.
  auto deck = smallDeck(1, 1.05, true, [](Teuchos::ParameterList& d) {
    stretchedTether(d);
    d.sublist("Adhesion").set("Enabled", true);
  });
  auto s = makeScene(*deck);
  const std::vector<double>& x = s.initialPositions();
  auto& bonds = s.bonds().bonds(0);
  const mesh::Vec3 p = s.bonds().receptors(0).position(s.cell(0), x.data(), 0);
  bonds.setState(0, {1.0, mesh::Vec3(p[0] + 0.2, 0.0, p[2])});
  std::vector<double> u;
  s.velocity(0.0, x, u);
  const std::vector<double>* external = s.externalForces(0);
  ASSERT_NE(external, nullptr);
  mesh::Vec3 spread = mesh::Vec3::Zero();
  for (int k = 0; k < s.cell(0).numNodes(); ++k) {
    spread += mesh::nodeAt(external->data(), k);
  }
  const mesh::Vec3 expected = bonds.force(0, p) + s.tether().state(s.cell(0), x.data()).force;
  EXPECT_LT((spread - expected).norm(), 1e-13 * expected.norm());
}

} // namespace
