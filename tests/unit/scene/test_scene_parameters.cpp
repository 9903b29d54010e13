#include "SceneTestDecks.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/scene/SceneDescription.hpp>
#include <capsula/scene/SceneParameters.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace {

namespace core = capsula::core;
namespace scene = capsula::scene;
using scene::testing::smallDeck;

// The message of the InputError that `build` throws ("" if none).
std::string inputError(const std::function<void()>& build)
{
  try {
    build();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

std::string validationError(const std::function<void(Teuchos::ParameterList&)>& tweak)
{
  return inputError([&] { smallDeck(1, 2.0, true, tweak); });
}

TEST(SceneParameters, DeclaresOneSublistPerCellOfTheDeck)
{
  auto deck = smallDeck(1, 2.0, true, [](Teuchos::ParameterList& d) {
    d.sublist("Cells").sublist("Cell 1").set("Center", scene::testing::realArray({3.0, 2.0, 0.0}));
    d.sublist("Cells").sublist("Cell 1").set("Membrane law", std::string("NeoHookean"));
  });
  const auto description = scene::describeScene(*deck);
  ASSERT_EQ(description.numCells(), 2);
  EXPECT_EQ(description.cells[1].path, "Cells/Cell 1");
  EXPECT_EQ(description.cells[1].membraneLaw, "NeoHookean");
  EXPECT_EQ(description.cells[0].membraneLaw, "Skalak"); // the default
  EXPECT_DOUBLE_EQ(description.capillaryNumber, 0.3);
  EXPECT_TRUE(description.wall);
  EXPECT_FALSE(description.anyFixedHeight());
  // Every default is filled in: the deck is a complete record.
  EXPECT_TRUE(deck->sublist("Cells").sublist("Cell 1").isParameter("Area dilation C"));
  EXPECT_TRUE(deck->sublist("Discretisation").isParameter("Singular quadrature points"));
}

TEST(SceneParameters, RejectsBadValuesNamingTheKey)
{
  EXPECT_NE(validationError([](Teuchos::ParameterList& d) {
              d.sublist("Flow").set("Capillary number", 0.0);
            }).find("'Flow/Capillary number'"),
            std::string::npos);
  EXPECT_NE(validationError([](Teuchos::ParameterList& d) {
              d.sublist("Flow").set("Capillary number", -0.3);
            }).find("'Flow/Capillary number'"),
            std::string::npos);
  EXPECT_NE(validationError([](Teuchos::ParameterList& d) {
              d.sublist("Cells").sublist("Cell 0").set("Area dilation C", 0.0);
            }).find("'Cells/Cell 0/Area dilation C'"),
            std::string::npos);
  EXPECT_NE(validationError([](Teuchos::ParameterList& d) {
              d.sublist("Cells").sublist("Cell 0").set("Shear modulus", -1.0);
            }).find("'Cells/Cell 0/Shear modulus'"),
            std::string::npos);
  const std::string law = validationError([](Teuchos::ParameterList& d) {
    d.sublist("Cells").sublist("Cell 0").set("Membrane law", std::string("Hookean"));
  });
  EXPECT_NE(law.find("'Cells/Cell 0/Membrane law'"), std::string::npos) << law;
  EXPECT_NE(law.find("NeoHookean"), std::string::npos) << law;
  EXPECT_NE(validationError([](Teuchos::ParameterList& d) {
              d.sublist("Cells").sublist("Cell 0").set("Mesh level", 9);
            }).find("'Cells/Cell 0/Mesh level' = 9"),
            std::string::npos);
  // A misspelt cell sublist is an unknown key, not a silently ignored cell.
  const std::string misspelt =
      validationError([](Teuchos::ParameterList& d) { d.sublist("Cells").sublist("Cel 1").set("Mesh level", 1); });
  EXPECT_NE(misspelt.find("Cel 1"), std::string::npos) << misspelt;
}

TEST(SceneDescription, RejectsInconsistentScenes)
{
  const auto described = [](const std::function<void(Teuchos::ParameterList&)>& tweak, bool wall = true) {
    return inputError([&] { scene::describeScene(*smallDeck(1, 2.0, wall, tweak)); });
  };
  EXPECT_NE(described([](Teuchos::ParameterList& d) {
              d.sublist("Cells").sublist("Cell 2").set("Center", scene::testing::realArray({5.0, 2.0, 0.0}));
            }).find("without gaps"),
            std::string::npos);
  EXPECT_NE(described([](Teuchos::ParameterList& d) { d.sublist("Cells").sublist("Cell 0").set("Fixed height", true); },
                      false)
                .find("'Cells/Cell 0/Fixed height' is true but 'Wall/Enabled' is false"),
            std::string::npos);
}

} // namespace
