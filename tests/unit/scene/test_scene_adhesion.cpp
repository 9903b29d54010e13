// Receptor-ligand bonds in a scene: built only when 'Adhesion/Enabled' asks for them, their
// spring forces reach the membrane whole, bonds form within the reaction distance of the
// wall and nowhere else, and the inputs that cannot work are refused naming the key.
#include "SceneTestDecks.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/scene/Scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace {

namespace core = capsula::core;
namespace mesh = capsula::mesh;
namespace scene = capsula::scene;
using scene::testing::makeScene;
using scene::testing::realArray;
using scene::testing::sceneRefusal;
using scene::testing::smallDeck;

// Rates that make bonds form at once within reach: k_on0 n_L = 100 k at k_B T = 1e-2 G a^2,
// where the stretch of a bond formed from 0.05 a up changes the rate by exp(-0.05) only.
void fastBinding(Teuchos::ParameterList& deck, const std::string& kinetics)
{
  auto& adhesion = deck.sublist("Adhesion");
  adhesion.set("Enabled", true);
  adhesion.set("Kinetics", kinetics);
  adhesion.set("On-rate", 1.0);
  adhesion.set("Off-rate", 0.0);
  adhesion.set("Thermal energy", 1e-2);
}

double meanComponent(const std::vector<double>& u, int d)
{
  double sum = 0.0;
  for (std::size_t i = static_cast<std::size_t>(d); i < u.size(); i += 3) {
    sum += u[i];
  }
  return sum / static_cast<double>(u.size() / 3);
}

TEST(SceneAdhesion, BuiltOnlyWhenEnabled)
{
  for (bool enabled : {false, true}) {
    auto deck =
        smallDeck(1, 1.6, true, [&](Teuchos::ParameterList& d) { d.sublist("Adhesion").set("Enabled", enabled); });
    auto s = makeScene(*deck);
    EXPECT_EQ(s.hasBonds(), enabled);
    EXPECT_EQ(s.externalForces(0) != nullptr, enabled);
    const bool named = std::any_of(s.terms().begin(), s.terms().end(),
                                   [](const std::string& t) { return t.find("adhesion:") != std::string::npos; });
    EXPECT_EQ(named, enabled);
    if (enabled) {
      // 50 per unit reference area, each element's count rounded up or down at random: the
      // total deviates by at most a few times sqrt(80 x 1/4) ~ 4.5 from its expectation.
      double area = 0.0;
      for (double a : mesh::elementAreas(s.cell(0), s.referencePositions(0).data())) {
        area += a;
      }
      EXPECT_NEAR(s.bonds().receptors(0).size(), 50.0 * area, 25.0);
      EXPECT_EQ(s.bonds().bondCount(), 0.0); // all free at the start
    }
  }
}

TEST(SceneAdhesion, BondForcesReachTheMembraneWhole)
{
  // A sphere 0.04 a above the wall, its receptors below 0.1 a bound by hand (k_off = 0:
  // permanent) to ligands 0.05 a upstream of their feet: stretched bonds that pull down and
  // upstream. The nodal forces of virtual work sum to the spring forces (sum phi_k = 1),
  // and the membrane passes them to the fluid: its nodal forces F_k = dE/dx_k - f_ext sum to
  // minus them, since an unstressed sphere has dE/dx = 0 up to round-off.
  std::vector<double> meanU;
  for (bool bound : {false, true}) {
    auto deck = smallDeck(1, 1.04, true, [](Teuchos::ParameterList& d) { fastBinding(d, "Mean field"); });
    auto s = makeScene(*deck);
    const std::vector<double>& x = s.initialPositions();
    mesh::Vec3 expected = mesh::Vec3::Zero();
    int count = 0;
    auto& bonds = s.bonds().bonds(0);
    for (int r = 0; bound && r < bonds.size(); ++r) {
      const mesh::Vec3 p = s.bonds().receptors(0).position(s.cell(0), x.data(), r);
      if (p[1] < 0.1) {
        bonds.setState(r, {1.0, mesh::Vec3(p[0] - 0.05, 0.0, p[2])});
        expected += bonds.force(r, p);
        ++count;
      }
    }
    std::vector<double> u;
    s.velocity(0.0, x, u);
    meanU.push_back(meanComponent(u, 0));
    mesh::Vec3 spread = mesh::Vec3::Zero(), membrane = mesh::Vec3::Zero();
    const std::vector<double>& f = *s.externalForces(0);
    for (int k = 0; k < s.cell(0).numNodes(); ++k) {
      spread += mesh::nodeAt(f.data(), k);
      membrane += s.membrane(0).nodalForces()[static_cast<std::size_t>(k)];
    }
    if (!bound) {
      EXPECT_EQ(spread.norm(), 0.0);
      continue;
    }
    ASSERT_GT(count, 5);
    EXPECT_LT(expected[1], 0.0); // towards the wall
    EXPECT_LT(expected[0], 0.0); // upstream
    // Sums of O(count) terms of size |F|: round-off ~1e-15 |F| per term.
    EXPECT_LT((spread - expected).norm(), 1e-12 * expected.norm())
        << spread.transpose() << " vs " << expected.transpose();
    EXPECT_LT((membrane + expected).norm(), 1e-10 * expected.norm()) << membrane.transpose();
  }
  // Held upstream, the cell moves slower along the flow.
  EXPECT_LT(meanU[1], meanU[0]);
}

TEST(SceneAdhesion, BondsFormWithinReachAndNotBeyond)
{
  // 'Reaction distance' 0.05 a: a sphere whose lowest node is 0.03 a up has receptors in
  // reach, one 0.3 a up has none.
  for (const char* kinetics : {"Mean field", "Stochastic"}) {
    for (double height : {1.03, 1.3}) {
      auto deck = smallDeck(1, height, true, [&](Teuchos::ParameterList& d) { fastBinding(d, kinetics); });
      auto s = makeScene(*deck);
      const std::vector<double>& x = s.initialPositions();
      const auto events = s.updateBonds(x, 0.1, 1);
      const auto& bonds = s.bonds().bonds(0);
      int reachable = 0;
      for (int r = 0; r < bonds.size(); ++r) {
        const double h = s.bonds().receptors(0).position(s.cell(0), x.data(), r)[1];
        reachable += h <= 0.05 ? 1 : 0;
        if (bonds.state(r).occupancy > 0.0) {
          EXPECT_LE(h, 0.05) << kinetics << ": receptor " << r << " bound from " << h;
          EXPECT_EQ(bonds.state(r).anchor[1], 0.0);
        }
      }
      if (height < 1.1) {
        ASSERT_GT(reachable, 0);
        // k_on dt >= 10 exp(-0.05): every receptor in reach binds but for ~5e-5 of them.
        EXPECT_GT(s.bonds().bondCount(), 0.9 * reachable) << kinetics;
      } else {
        EXPECT_EQ(reachable, 0);
        EXPECT_EQ(s.bonds().bondCount(), 0.0) << kinetics;
      }
      if (std::string(kinetics) == "Stochastic") {
        EXPECT_EQ(events.formed, static_cast<int>(s.bonds().bondCount()));
      }
    }
  }
}

TEST(SceneAdhesion, RefusesInputsThatCannotWork)
{
  const auto enable = [](Teuchos::ParameterList& d) -> Teuchos::ParameterList& {
    d.sublist("Adhesion").set("Enabled", true);
    return d.sublist("Adhesion");
  };
  EXPECT_NE(sceneRefusal([&](auto& d) { enable(d).set("Receptor density", -1.0); }).find("'Adhesion/Receptor density'"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) { enable(d).set("Ligand density", -5.0); }).find("'Adhesion/Ligand density'"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) { enable(d).set("Spring constant", 0.0); }).find("'Adhesion/Spring constant'"),
            std::string::npos);
  // Off, a zero spring constant builds nothing and is no error.
  EXPECT_EQ(sceneRefusal([](auto& d) { d.sublist("Adhesion").set("Spring constant", 0.0); }), "");
  EXPECT_NE(sceneRefusal([&](auto& d) {
              enable(d).set("Ligand patch", realArray({1.0, -1.0, -1.0, 1.0}));
            }).find("'Adhesion/Ligand patch'"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) {
              enable(d).set("Ligand patch", realArray({-1.0, 1.0}));
            }).find("'Adhesion/Ligand patch'"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) { enable(d); }, false).find("'Wall/Enabled' is false"), std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) {
              enable(d);
              d.sublist("Cells").sublist("Cell 0").set("Membrane forces", "Contour integral");
            }).find("'Adhesion/Enabled' is true but 'Cells/Cell 0/Membrane forces'"),
            std::string::npos);
  EXPECT_NE(sceneRefusal([&](auto& d) {
              enable(d);
              d.sublist("Mesh regularisation").set("Enabled", true);
            }).find("'Mesh regularisation/Enabled'"),
            std::string::npos);
}

} // namespace

namespace ligand_wall_tests {

using scene::testing::smallDeck;

// The deck of a level-1 sphere 0.03 below the upper wall of the periodic Poiseuille channel
// H = 4 (box 6 x 6) with adhesion on, the ligands where `wall` says.
Teuchos::RCP<Teuchos::ParameterList> channelAdhesionDeck(const std::string& wall, double height = 4.0)
{
  return smallDeck(1, 1.6, true, [&](Teuchos::ParameterList& d) {
    d.sublist("Wall").set("Channel height", height);
    d.sublist("Domain").set("Periodic length x", 6.0);
    d.sublist("Domain").set("Periodic length z", 6.0);
    d.sublist("Cells").sublist("Cell 0").set("Center", realArray({1.0, height - 1.03, 1.0}));
    d.sublist("Flow").set("Profile", "Poiseuille");
    d.sublist("Adhesion").set("Enabled", true);
    d.sublist("Adhesion").set("Ligand wall", wall);
  });
}

TEST(SceneAdhesion, TheUpperLigandWallIsTheChannelsUpperWall)
{
  const scene::SceneDescription upper = scene::describeScene(*channelAdhesionDeck("Upper"));
  EXPECT_EQ(upper.adhesion.ligandWall.height, 4.0);
  EXPECT_EQ(upper.adhesion.ligandWall.fluidSide, -1);
  // In the periodic box the ligand patch repeats with the box.
  EXPECT_EQ(upper.adhesion.ligandPatch.periodX, 6.0);
  EXPECT_EQ(upper.adhesion.ligandPatch.periodZ, 6.0);
  const scene::SceneDescription lower = scene::describeScene(*channelAdhesionDeck("Lower"));
  EXPECT_EQ(lower.adhesion.ligandWall.height, 0.0);
  EXPECT_EQ(lower.adhesion.ligandWall.fluidSide, 1);
}

TEST(SceneAdhesion, RefusesAnUpperLigandWallWithoutAChannelOrSlidingAndAPatchOutsideTheBox)
{
  EXPECT_NE(sceneRefusal([](auto& d) {
              d.sublist("Adhesion").set("Enabled", true);
              d.sublist("Adhesion").set("Ligand wall", "Upper");
            }).find("'Adhesion/Ligand wall' = Upper, but the domain has no upper wall"),
            std::string::npos);
  try {
    auto deck = channelAdhesionDeck("Upper");
    deck->sublist("Flow").set("Profile", "Shear");
    scene::describeScene(*deck);
    FAIL() << "ligands on the sliding upper wall of plane Couette flow were accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Adhesion/Ligand wall' = Upper with 'Flow/Profile' = Shear"),
              std::string::npos)
        << e.what();
  }
  try {
    auto deck = channelAdhesionDeck("Upper");
    deck->sublist("Adhesion").set("Ligand patch", realArray({4.0, 7.0, 0.0, 1.0}));
    scene::describeScene(*deck);
    FAIL() << "a ligand patch reaching out of the periodic box was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Adhesion/Ligand patch' spans x in [4, 7]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'Domain/Periodic length x'"), std::string::npos) << e.what();
  }
}

} // namespace ligand_wall_tests
