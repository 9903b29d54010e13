// The deck of cell3d and twocell3d (SceneRunDeck.hpp): complete after validation, and its
// Output sublist read with the checks the validators cannot make alone
// (SceneOutputSettings.hpp).
#include "SceneRunFixture.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/run/SceneOutputSettings.hpp>
#include <capsula/scene/SceneDescription.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace {

namespace core = capsula::core;
namespace run = capsula::run;
namespace scene = capsula::scene;
using run::testing::smallDeck;

TEST(SceneRunDeck, FillsInEveryDefault)
{
  const auto deck = smallDeck(1, 2.0, true);
  EXPECT_TRUE(deck->sublist("Time integration").isParameter("Method"));
  EXPECT_TRUE(deck->sublist("Discretisation").isParameter("Singular quadrature points"));
  EXPECT_TRUE(deck->sublist("Mesh adaption").isParameter("Enabled"));
  EXPECT_TRUE(deck->sublist("Output").sublist("Stability").isParameter("Minimum angle"));
  const auto settings = run::readSceneOutputSettings(*deck, scene::describeScene(*deck));
  EXPECT_DOUBLE_EQ(settings.interval, 0.1);
  EXPECT_TRUE(settings.checkpoint);
}

TEST(SceneOutputSettings, RejectsOutputsTheSceneCannotHave)
{
  const auto described = [](const std::function<void(Teuchos::ParameterList&)>& tweak,
                            bool wall = true) -> std::string {
    try {
      const auto deck = smallDeck(1, 2.0, wall, tweak);
      run::readSceneOutputSettings(*deck, scene::describeScene(*deck));
    } catch (const core::InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(described([](Teuchos::ParameterList& d) {
              d.sublist("Output").set("Flow probes", scene::testing::realArray({1.0, 2.0, 3.0, 4.0}));
            }).find("'Output/Flow probes' has 4 numbers"),
            std::string::npos);
  EXPECT_NE(described([](Teuchos::ParameterList& d) {
              d.sublist("Output").set("Flow probes", scene::testing::realArray({1.0, -2.0, 3.0}));
            }).find("not in the fluid"),
            std::string::npos);
  EXPECT_NE(
      described(
          [](Teuchos::ParameterList& d) { d.sublist("Output").sublist("Wall shear stress").set("Enabled", true); },
          false)
          .find("there is no wall"),
      std::string::npos);
}

} // namespace
