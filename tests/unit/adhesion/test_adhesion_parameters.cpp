// The "Adhesion" and "Contact" deck sublists: defaults, and bad input refused with a message
// that names the key.
#include <capsula/adhesion/AdhesionParameters.hpp>
#include <capsula/adhesion/ContactParameters.hpp>
#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace adhesion = capsula::adhesion;
namespace core = capsula::core;

namespace {

Teuchos::RCP<Teuchos::ParameterList> adhesionDeck(const std::string& adhesionXml, const std::string& contactXml = "")
{
  Teuchos::ParameterList valid("Capsula");
  adhesion::declareAdhesionParameters(core::declareSublist(valid, "Adhesion", "Bonds"));
  adhesion::declareContactParameters(core::declareSublist(valid, "Contact", "Repulsion"));
  auto deck = core::readDeckFromString("<ParameterList name=\"Capsula\"><ParameterList name=\"Adhesion\">" +
                                           adhesionXml + "</ParameterList><ParameterList name=\"Contact\">" +
                                           contactXml + "</ParameterList></ParameterList>",
                                       "deck.xml");
  core::validateDeck(*deck, valid, "deck.xml");
  return deck;
}

// The message of the InputError `f` throws (empty if it throws none).
template <typename F>
std::string inputErrorOf(F&& f)
{
  try {
    f();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

std::string realParameter(const std::string& key, double value)
{
  return "<Parameter name=\"" + key + "\" type=\"double\" value=\"" + std::to_string(value) + "\"/>";
}

} // namespace

TEST(AdhesionParameters, DefaultsAreTheDocumentedOnes)
{
  const auto deck = adhesionDeck("");
  const auto s = adhesion::readAdhesionParameters(deck->sublist("Adhesion"));
  EXPECT_FALSE(s.enabled);
  EXPECT_EQ(s.receptorDensity, 50.0);
  EXPECT_EQ(s.springConstant, 10.0);
  EXPECT_EQ(s.model, adhesion::BondModel::Slip);
  EXPECT_EQ(s.kinetics, adhesion::BondKinetics::Stochastic);
  EXPECT_EQ(s.seed, 1u);
  EXPECT_FALSE(s.ligandPatch.bounded()); // {}: the whole wall
  EXPECT_TRUE(s.ligandPatch.contains(1e6, -1e6));
  const auto c = adhesion::readContactParameters(deck->sublist("Contact"));
  EXPECT_FALSE(c.enabled);
  EXPECT_EQ(c.range, 0.05);
  EXPECT_EQ(c.load, adhesion::ContactLoad::NodalArea);
  const auto work = adhesionDeck("", R"xml(<Parameter name="Load" type="string" value="Virtual work"/>)xml");
  EXPECT_EQ(adhesion::readContactParameters(work->sublist("Contact")).load, adhesion::ContactLoad::VirtualWork);
}

TEST(AdhesionParameters, ChoicesAndPatchReachTheSettings)
{
  const auto deck = adhesionDeck(R"xml(
    <Parameter name="Enabled" type="bool" value="true"/>
    <Parameter name="Bond model" type="string" value="Catch-slip (Dembo)"/>
    <Parameter name="Kinetics" type="string" value="Mean field"/>
    <Parameter name="Ligand patch" type="Array(double)" value="{-2, 3, -1, 1}"/>
    <Parameter name="Seed" type="int" value="42"/>)xml");
  const auto s = adhesion::readAdhesionParameters(deck->sublist("Adhesion"));
  EXPECT_TRUE(s.enabled);
  EXPECT_EQ(s.model, adhesion::BondModel::CatchSlip);
  EXPECT_EQ(s.kinetics, adhesion::BondKinetics::MeanField);
  EXPECT_EQ(s.seed, 42u);
  EXPECT_TRUE(s.ligandPatch.contains(2.9, 0.0));
  EXPECT_FALSE(s.ligandPatch.contains(3.1, 0.0));
}

TEST(AdhesionParameters, NegativeDensitiesAreRefusedNamingTheKey)
{
  for (const std::string key : {"Receptor density", "Ligand density", "Patch radius"}) {
    // By the deck's validator ...
    const std::string byDeck = inputErrorOf([&] { adhesionDeck(realParameter(key, -1.0)); });
    EXPECT_NE(byDeck.find("Adhesion/" + key), std::string::npos) << byDeck;
    // ... and by the reader, for a list built in code.
    auto list = adhesionDeck("")->sublist("Adhesion");
    list.remove(key); // drops the validator with the entry
    list.set(key, -1.0);
    const std::string byReader = inputErrorOf([&] { adhesion::readAdhesionParameters(list); });
    EXPECT_NE(byReader.find("'Adhesion/" + key + "'"), std::string::npos) << byReader;
  }
}

TEST(AdhesionParameters, ZeroSpringConstantIsRefusedOnlyWhenEnabled)
{
  const auto off = adhesionDeck(realParameter("Spring constant", 0.0));
  EXPECT_NO_THROW(adhesion::readAdhesionParameters(off->sublist("Adhesion")));
  const auto on = adhesionDeck(realParameter("Spring constant", 0.0) +
                               "<Parameter name=\"Enabled\" type=\"bool\" value=\"true\"/>");
  const std::string message = inputErrorOf([&] { adhesion::readAdhesionParameters(on->sublist("Adhesion")); });
  EXPECT_NE(message.find("'Adhesion/Spring constant'"), std::string::npos) << message;
}

TEST(AdhesionParameters, LigandPatchOffTheWallIsRefused)
{
  const adhesion::WallRectangle wall{-10.0, 10.0, -5.0, 5.0};
  const auto inside =
      adhesionDeck(R"xml(<Parameter name="Ligand patch" type="Array(double)" value="{-1, 1, -1, 1}"/>)xml");
  EXPECT_NO_THROW(adhesion::readAdhesionParameters(inside->sublist("Adhesion"), "Adhesion", wall));
  for (const std::string patch : {"{5, 12, -1, 1}", "{-1, 1, -6, 1}", "{20, 30, 0, 1}", "{1, 0, -1, 1}"}) {
    const auto deck = adhesionDeck("<Parameter name=\"Ligand patch\" type=\"Array(double)\" value=\"" + patch + "\"/>");
    const std::string message =
        inputErrorOf([&] { adhesion::readAdhesionParameters(deck->sublist("Adhesion"), "Adhesion", wall); });
    EXPECT_NE(message.find("'Adhesion/Ligand patch'"), std::string::npos) << patch << ": " << message;
  }
  // The empty patch means the whole of the simulated wall.
  const auto whole = adhesion::readAdhesionParameters(adhesionDeck("")->sublist("Adhesion"), "Adhesion", wall);
  EXPECT_EQ(whole.ligandPatch.xMax, 10.0);
  const auto three = adhesionDeck(R"xml(<Parameter name="Ligand patch" type="Array(double)" value="{0, 1, 2}"/>)xml");
  EXPECT_NE(inputErrorOf([&] { adhesion::readAdhesionParameters(three->sublist("Adhesion")); }).find("Ligand patch"),
            std::string::npos);
}

TEST(ContactParameters, NonPositiveRangeIsRefusedNamingTheKey)
{
  const std::string message = inputErrorOf([] { adhesionDeck("", realParameter("Range", 0.0)); });
  EXPECT_NE(message.find("Contact/Range"), std::string::npos) << message;
}
