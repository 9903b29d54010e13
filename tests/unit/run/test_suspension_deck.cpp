// The suspension app's deck (SuspensionApplication.hpp, suspension/SuspensionDeck.hpp): the
// cell types placed as 'Cells/Cell k' at the hematocrit asked for (within 1%), clear of each
// other, of their periodic images and of both walls, the same for the same seed; each cell's
// 'Type'; and the refusals of bad input, each naming the key.
#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/domain/DomainParameters.hpp>
#include <capsula/mesh/CellSurfaceParameters.hpp>
#include <capsula/run/SuspensionApplication.hpp>
#include <capsula/scene/CellPlacement.hpp>
#include <capsula/suspension/HematocritProfile.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace suspension_deck_tests {

namespace core = capsula::core;
namespace mesh = capsula::mesh;
namespace run = capsula::run;
namespace suspension = capsula::suspension;

// Red cells filling the hematocrit and `platelets` platelets, level 1, in a channel H = 6
// periodic in a box 8 x 8.4 (the demo deck's), with `extra` XML inside 'Suspension'.
std::string deckXml(double hematocrit, int platelets, const std::string& extraTypeKeys = "",
                    const std::string& extraSuspension = "", const std::string& extraTop = "")
{
  return R"xml(<ParameterList name="suspension3d">
  <ParameterList name="Flow"><Parameter name="Profile" type="string" value="Poiseuille"/></ParameterList>
  <ParameterList name="Wall"><Parameter name="Channel height" type="double" value="6.0"/>
    <Parameter name="Minimum gap" type="double" value="0.2"/></ParameterList>
  <ParameterList name="Domain"><Parameter name="Periodic length x" type="double" value="8.0"/>
    <Parameter name="Periodic length z" type="double" value="8.4"/></ParameterList>)xml" +
         extraTop + R"xml(
  <ParameterList name="Suspension">
    <Parameter name="Hematocrit" type="double" value=")xml" +
         std::to_string(hematocrit) + R"xml("/>)xml" + extraSuspension + R"xml(
    <ParameterList name="Cell types">
      <ParameterList name="red_cell">
        <Parameter name="Shape" type="string" value="Biconcave"/>
        <Parameter name="Radius" type="double" value="1.38577"/>
        <Parameter name="Mesh level" type="int" value="1"/>
        <Parameter name="Viscosity ratio" type="double" value="5"/>)xml" +
         extraTypeKeys + R"xml(
      </ParameterList>
      <ParameterList name="platelet">
        <Parameter name="Count" type="int" value=")xml" +
         std::to_string(platelets) + R"xml("/>
        <Parameter name="Shape" type="string" value="Spheroid"/>
        <Parameter name="Semi-axes" type="Array(double)" value="{0.5, 0.5, 0.125}"/>
        <Parameter name="Mesh level" type="int" value="1"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>)xml";
}

Teuchos::RCP<Teuchos::ParameterList> validated(const std::string& xml)
{
  auto deck = core::readDeckFromString(xml, "test");
  core::validateDeck(*deck, *run::validSuspensionRunParameters(*deck, "suspension3d", run::standardSceneLibraries()),
                     "test");
  return deck;
}

Teuchos::ParameterList placed(const std::string& xml)
{
  return run::placedSceneDeck(*validated(xml), "suspension3d", run::standardSceneLibraries(), nullptr);
}

// The message of the core::InputError that `action` throws ("" if none).
template <class Action>
std::string inputError(Action action)
{
  try {
    action();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

struct Cells {
  std::vector<mesh::SurfaceMesh> surfaces;
  std::vector<std::string> paths, types;
};

Cells cellsOf(const Teuchos::ParameterList& deck)
{
  Cells out;
  const auto& cells = deck.sublist("Cells");
  for (int c = 0; cells.isSublist("Cell " + std::to_string(c)); ++c) {
    out.paths.push_back("Cells/Cell " + std::to_string(c));
    const auto& cell = cells.sublist("Cell " + std::to_string(c));
    out.surfaces.push_back(mesh::buildCellSurface(cell, out.paths.back()));
    out.types.push_back(cell.get<std::string>("Type"));
  }
  return out;
}

// 0.1 of the box 8 x 6 x 8.4 is 10 level-1 red cells (faceted volume 4.047): 0.10037.
TEST(SuspensionDeck, PlacesTheHematocritWithinOnePercentClearOfEachOtherAndTheWalls)
{
  const Teuchos::ParameterList deck = placed(deckXml(0.1, 3));
  const Cells cells = cellsOf(deck);
  ASSERT_EQ(cells.surfaces.size(), 13u);
  std::vector<const mesh::SurfaceMesh*> reds, all;
  for (std::size_t c = 0; c < cells.surfaces.size(); ++c) {
    all.push_back(&cells.surfaces[c]);
    if (cells.types[c] == "red_cell") {
      reds.push_back(&cells.surfaces[c]);
    } else {
      EXPECT_EQ(cells.types[c], "platelet");
    }
  }
  EXPECT_EQ(reds.size(), 10u);
  // The red cells come first (the largest type), so the columns of a type are together.
  EXPECT_EQ(cells.types.front(), "red_cell");
  EXPECT_EQ(cells.types.back(), "platelet");
  // The hematocrit the run's own profile measures, to 1% of the target.
  const auto domain = capsula::domain::readDomain(deck);
  const double reached = suspension::hematocritProfile(reds, domain, 6).mean;
  EXPECT_NEAR(reached, 0.1, 0.001) << reached;
  // Every gap the scene checks at start-up holds, with the periodic images.
  for (std::size_t c = 0; c < all.size(); ++c) {
    EXPECT_NO_THROW(capsula::scene::requireWallGaps(*all[c], cells.paths[c], domain, 0.2));
  }
  EXPECT_NO_THROW(capsula::scene::requireNoOverlap(all, cells.paths, 0.05, domain));
  // Each cell keeps its type's keys; the red cells count for the hematocrit outputs.
  EXPECT_EQ(deck.sublist("Cells").sublist("Cell 0").get<double>("Viscosity ratio"), 5.0);
  EXPECT_EQ(deck.sublist("Output").sublist("Suspension").get<std::string>("Hematocrit type"), "red_cell");
  EXPECT_TRUE(deck.sublist("Output").sublist("Suspension").get<bool>("Enabled"));
}

TEST(SuspensionDeck, TheSameSeedPlacesTheSameCells)
{
  const Cells first = cellsOf(placed(deckXml(0.1, 2)));
  const Cells again = cellsOf(placed(deckXml(0.1, 2)));
  const Cells other = cellsOf(placed(deckXml(0.1, 2, "", R"xml(<Parameter name="Seed" type="int" value="2"/>)xml")));
  ASSERT_EQ(first.surfaces.size(), again.surfaces.size());
  double moved = 0.0;
  for (std::size_t c = 0; c < first.surfaces.size(); ++c) {
    EXPECT_EQ(first.surfaces[c].positions(), again.surfaces[c].positions());
    moved = std::max(moved, (first.surfaces[c].position(0) - other.surfaces[c].position(0)).norm());
  }
  EXPECT_GT(moved, 0.1);
}

TEST(SuspensionDeck, BadInputIsRefusedNamingTheKey)
{
  // A key a cell does not have, and one the placement sets.
  EXPECT_NE(inputError([] {
              validated(deckXml(0.1, 2, R"xml(<Parameter name="Radios" type="double" value="1"/>)xml"));
            }).find("Radios"),
            std::string::npos);
  EXPECT_NE(inputError([] {
              validated(deckXml(0.1, 2, R"xml(<Parameter name="Center" type="Array(double)" value="{0, 3, 0}"/>)xml"));
            }).find("Center"),
            std::string::npos);
  // Two types that both fill the hematocrit (the platelets' Count left at 0).
  EXPECT_NE(inputError([] { placed(deckXml(0.1, 0)); })
                .find("'Suspension/Cell types/red_cell/Count' and "
                      "'platelet/Count' are both 0"),
            std::string::npos);
  // A hematocrit that 7 or 8 cells miss by more than 1%, and one that cannot be packed.
  EXPECT_NE(inputError([] { placed(deckXml(0.075, 2)); }).find("'Suspension/Hematocrit' = 0.075 cannot be met"),
            std::string::npos);
  std::string wide = deckXml(0.1, 2, "", R"xml(<Parameter name="Attempts" type="int" value="200"/>)xml");
  wide.replace(wide.find("{0.5, 0.5, 0.125}"), 17, "{5.0, 5.0, 1.25}"); // wider than the box
  EXPECT_NE(inputError([&] { placed(wide); }).find("The suspension jams: cell 1 of the 2 of type 'platelet'"),
            std::string::npos);
  // Cells of its own, a type's name that is not a word, a box that is not a periodic channel.
  const std::string withCell =
      deckXml(0.1, 2, "", "",
              R"xml(<ParameterList name="Cells"><ParameterList name="Cell 0"></ParameterList></ParameterList>)xml");
  EXPECT_NE(inputError([&] { placed(withCell); }).find("'Cells/Cell 0' is given"), std::string::npos);
  std::string spaced = deckXml(0.1, 2);
  spaced.replace(spaced.find("\"platelet\""), 10, "\"big platelet\"");
  EXPECT_NE(inputError([&] { validated(spaced); }).find("'Suspension/Cell types/big platelet'"), std::string::npos);
  std::string unbounded = deckXml(0.1, 2);
  unbounded.replace(unbounded.find("value=\"8.4\""), 11, "value=\"0\"");
  EXPECT_NE(inputError([&] { placed(unbounded); }).find("'Domain/Periodic length z'"), std::string::npos);
}

// Every type counted, the hematocrit given too: it would have no effect.
TEST(SuspensionDeck, AHematocritWithoutEffectIsRefused)
{
  std::string counted = deckXml(0.1, 2);
  counted.replace(counted.find("<Parameter name=\"Shape\" type=\"string\" value=\"Biconcave\"/>"), 0,
                  R"xml(<Parameter name="Count" type="int" value="4"/>)xml");
  EXPECT_NE(inputError([&] { placed(counted); }).find("'Suspension/Hematocrit' is given, but every type"),
            std::string::npos);
  // Without the hematocrit the counts place 4 + 2 cells.
  counted.erase(counted.find("<Parameter name=\"Hematocrit\""),
                counted.find("/>", counted.find("<Parameter name=\"Hematocrit\"")) + 2 -
                    counted.find("<Parameter name=\"Hematocrit\""));
  EXPECT_EQ(cellsOf(placed(counted)).surfaces.size(), 6u);
}

} // namespace suspension_deck_tests
