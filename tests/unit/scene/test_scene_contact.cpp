// The contact repulsion in a scene: built only when 'Contact/Enabled' asks for it, and a
// membrane inside its range is pushed away from the wall.
#include "SceneTestDecks.hpp"

#include <capsula/scene/Scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

namespace scene = capsula::scene;
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

} // namespace
