// The contact repulsion in a scene: built only when 'Contact/Enabled' asks for it; a
// membrane inside its range is pushed away from the wall, the upper wall of a channel
// included; cells touch across the boundary of a periodic box as inside it.
#include "SceneTestDecks.hpp"

#include <capsula/adhesion/ContactRepulsion.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/periodic/PeriodicKernelLibrary.hpp>
#include <capsula/scene/Scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

namespace scene = capsula::scene;
namespace adhesion = capsula::adhesion;
namespace mesh = capsula::mesh;
using scene::testing::makeScene;
using scene::testing::smallDeck;

// Mean vertical velocity of the nodes.
double meanRise(const std::vector<double>& u)
{
  double sum = 0.0;
  for (std::size_t i = 1; i < u.size(); i += 3) {
    sum += u[i];
  }
  return sum / static_cast<double>(u.size() / 3);
}

TEST(SceneContact, RepulsionPushesAMembraneOffTheWall)
{
  // A sphere whose lowest node is 0.02 a above the wall, inside the 0.05 a range of the
  // repulsion: without contact the cell hardly moves vertically at rest (the wall lift of a
  // sphere vanishes, measured |mean u_y| ~1e-3 from the discretisation); with it the lowest
  // nodes are pushed up (pressure p_0 (delta/d - 2) ~ 30 G/a over their area) and the cell
  // rises. The bound 10x separates the two with room.
  std::vector<double> rise;
  for (bool contact : {false, true}) {
    auto deck = smallDeck(1, 1.02, true, [&](Teuchos::ParameterList& d) {
      d.sublist("Contact").set("Enabled", contact);
      d.sublist("Wall").set("Minimum gap", 0.0);
    });
    auto s = makeScene(*deck);
    const bool named = std::any_of(s.terms().begin(), s.terms().end(), [](const std::string& t) {
      return t.find("contact repulsion") != std::string::npos;
    });
    EXPECT_EQ(named, contact);
    std::vector<double> u;
    s.velocity(0.0, s.initialPositions(), u);
    rise.push_back(meanRise(u));
  }
  EXPECT_GT(rise[1], 0.0);
  EXPECT_GT(rise[1], 10.0 * std::abs(rise[0])) << "without " << rise[0] << ", with " << rise[1];
}

// The upper wall y = H repels as the lower wall does, mirrored: a sphere 0.02 below it takes
// at each node the reflection (y -> -y) of the force on its mirror node of a sphere 0.02
// above the lower wall (the level-2 sphere is symmetric about its equator). Both contact
// loads; the forces are sums of the same terms, so they agree to round-off (1e-12 of the
// largest nodal force). The lower wall's sign or gap used for the upper wall pushes
// the membrane into the wall or not at all: an O(1) difference.
TEST(ContactRepulsion, TheUpperWallRepelsAsTheMirrorOfTheLowerWall)
{
  const double height = 5.0;
  const mesh::Vec3 lowerCentre(0.2, 1.02, -0.3), upperCentre(0.2, height - 1.02, -0.3);
  const mesh::SurfaceMesh lower = mesh::makeSphere(2, 1.0, {lowerCentre});
  const mesh::SurfaceMesh upper = mesh::makeSphere(2, 1.0, {upperCentre});
  for (const auto load : {adhesion::ContactLoad::NodalArea, adhesion::ContactLoad::VirtualWork}) {
    adhesion::ContactSettings contact;
    contact.enabled = true;
    contact.load = load;
    std::vector<double> fLower(3 * static_cast<std::size_t>(lower.numNodes()), 0.0), fUpper(fLower.size(), 0.0);
    const mesh::Vec3 totalLower = adhesion::addWallContactForces(contact, lower, lower.positionData(), fLower.data());
    const mesh::Vec3 totalUpper = adhesion::addWallContactForces(contact, upper, upper.positionData(), fUpper.data(),
                                                                 adhesion::ContactWall{height, -1});
    EXPECT_GT(totalLower[1], 0.1); // measured 0.53 (nodal area) and 0.42 (virtual work)
    EXPECT_NEAR(totalUpper[1], -totalLower[1], 1e-12 * totalLower[1]);
    double largest = 0.0, difference = 0.0;
    int matched = 0;
    for (int a = 0; a < lower.numNodes(); ++a) {
      const mesh::Vec3 mirror = lower.position(a) - lowerCentre;
      for (int b = 0; b < upper.numNodes(); ++b) {
        const mesh::Vec3 d = upper.position(b) - upperCentre;
        if (std::abs(d[0] - mirror[0]) + std::abs(d[1] + mirror[1]) + std::abs(d[2] - mirror[2]) > 1e-12) {
          continue;
        }
        ++matched;
        for (int i = 0; i < 3; ++i) {
          const double sign = i == 1 ? -1.0 : 1.0;
          largest = std::max(largest, std::abs(fLower[3 * a + i]));
          difference = std::max(difference, std::abs(fUpper[3 * b + i] - sign * fLower[3 * a + i]));
        }
      }
    }
    EXPECT_EQ(matched, lower.numNodes());
    EXPECT_GT(largest, 0.0);
    EXPECT_LT(difference, 1e-12 * largest);
  }
}

// Two unit spheres 0.03 apart (inside the 0.05 range) in a box 6 x 6 periodic along x and z,
// once inside the box and once with the second sphere a period away, so that they touch
// only across the boundary x = 0: the contact forces on every node are the same (the scene
// moves the second cell next to the first by a lattice vector, and the forces do not change
// under a translation), up to the round-off of the shifted positions (1e-12 of the largest
// force). Contact taken between the unfolded positions gives no force at all.
TEST(SceneContact, CellsTouchAcrossThePeriodicBoundaryAsInsideTheBox)
{
  std::vector<std::vector<std::vector<double>>> forces;
  for (const double secondX : {1.0 + 2.03, 1.0 + 2.03 - 6.0}) {
    auto deck = smallDeck(1, 1.6, true, [&](Teuchos::ParameterList& d) {
      d.sublist("Contact").set("Enabled", true);
      d.sublist("Cells").set("Minimum gap", 0.01);
      d.sublist("Cells").sublist("Cell 0").set("Center", scene::testing::realArray({1.0, 1.6, 2.0}));
      d.sublist("Cells").sublist("Cell 1") = d.sublist("Cells").sublist("Cell 0");
      d.sublist("Cells").sublist("Cell 1").set("Center", scene::testing::realArray({secondX, 1.6, 2.0}));
      d.sublist("Domain").set("Periodic length x", 6.0);
      d.sublist("Domain").set("Periodic length z", 6.0);
    });
    capsula::operators::KernelRegistry registry = capsula::operators::builtInKernels();
    capsula::periodic::registerPeriodicKernels(registry);
    scene::Scene s(scene::describeScene(*deck), *deck, Tpetra::getDefaultComm(), registry);
    std::vector<double> u;
    s.velocity(0.0, s.initialPositions(), u);
    const std::vector<double>* first = s.externalForces(0);
    const std::vector<double>* second = s.externalForces(1);
    ASSERT_TRUE(first != nullptr && second != nullptr) << "the contact force is a term of this scene";
    forces.push_back({*first, *second});
  }
  double largest = 0.0, difference = 0.0;
  for (std::size_t c = 0; c < 2; ++c) {
    for (std::size_t k = 0; k < forces[0][c].size(); ++k) {
      largest = std::max(largest, std::abs(forces[0][c][k]));
      difference = std::max(difference, std::abs(forces[0][c][k] - forces[1][c][k]));
    }
  }
  EXPECT_GT(largest, 0.1); // the pair is in contact: measured 0.42 at the closest nodes
  EXPECT_LT(difference, 1e-12 * largest);
}

} // namespace
