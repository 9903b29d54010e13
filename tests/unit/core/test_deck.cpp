// Decks: reading, validation messages (key path + deck name + requirement),
// defaults, --set overrides and the XML writer's round trip.
#include "capsula/core/Deck.hpp"
#include "capsula/core/Error.hpp"
#include "capsula/core/ParameterDeclaration.hpp"

#include <gtest/gtest.h>

using capsula::core::InputError;
namespace core = capsula::core;

namespace {

// A small valid list shaped like the real ones: nested sublists, every kind of value.
Teuchos::RCP<const Teuchos::ParameterList> validList()
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("Capsula"));
  auto& flow = core::declareSublist(*valid, "Flow", "Ambient flow");
  core::declareReal(flow, "Capillary number", 0.3, "Ca = mu k a / G", core::greaterThan(0.0));
  core::declareReal(flow, "Viscosity ratio", 1.0, "lambda", core::greaterThan(0.0));
  auto& cell = core::declareSublist(core::declareSublist(*valid, "Cells", "Cells"), "Cell 0", "A cell");
  core::declareInt(cell, "Mesh level", 2, "icosahedron subdivisions", 0, 5);
  core::declareChoice(cell, "Membrane law", "Skalak", {"NeoHookean", "Skalak"}, "membrane law");
  core::declareRealArray(cell, "Center", {0.0, 2.0, 0.0}, 3, "centroid");
  core::declareBool(cell, "Fixed height", false, "hold the height");
  core::declareString(*valid, "Title", "run", "a label");
  return valid;
}

std::string errorOf(const std::string& xml)
{
  try {
    auto deck = core::readDeckFromString(xml, "deck.xml");
    core::validateDeck(*deck, *validList(), "deck.xml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

bool contains(const std::string& text, const std::string& piece)
{
  return text.find(piece) != std::string::npos;
}

} // namespace

TEST(Deck, ValidDeckGetsEveryDefault)
{
  auto deck = core::readDeckFromString(R"(<ParameterList name="Capsula">
      <ParameterList name="Flow"><Parameter name="Capillary number" type="double" value="0.6"/></ParameterList>
    </ParameterList>)",
                                       "deck.xml");
  core::validateDeck(*deck, *validList(), "deck.xml");
  EXPECT_EQ(deck->sublist("Flow").get<double>("Capillary number"), 0.6);
  EXPECT_EQ(deck->sublist("Flow").get<double>("Viscosity ratio"), 1.0);
  EXPECT_EQ(deck->sublist("Cells").sublist("Cell 0").get<int>("Mesh level"), 2);
  EXPECT_EQ(deck->sublist("Cells").sublist("Cell 0").get<std::string>("Membrane law"), "Skalak");
}

TEST(Deck, UnknownKeyIsNamedWithPathDeckAndSuggestion)
{
  const auto msg = errorOf(R"(<ParameterList name="Capsula"><ParameterList name="Flow">
      <Parameter name="Capilary number" type="double" value="0.6"/></ParameterList></ParameterList>)");
  EXPECT_TRUE(contains(msg, "deck.xml")) << msg;
  EXPECT_TRUE(contains(msg, "unknown key 'Flow/Capilary number'")) << msg;
  EXPECT_TRUE(contains(msg, "Did you mean 'Flow/Capillary number'?")) << msg;
}

TEST(Deck, UnknownSublistIsRejected)
{
  const auto msg = errorOf(R"(<ParameterList name="Capsula"><ParameterList name="Wal"/></ParameterList>)");
  EXPECT_TRUE(contains(msg, "unknown key 'Wal'")) << msg;
}

TEST(Deck, WrongTypeIsNamed)
{
  const auto msg = errorOf(R"(<ParameterList name="Capsula"><ParameterList name="Flow">
      <Parameter name="Capillary number" type="string" value="fast"/></ParameterList></ParameterList>)");
  EXPECT_TRUE(contains(msg, "'Flow/Capillary number' has type string but must be of type double")) << msg;
}

TEST(Deck, IntegerWhereRealExpectedIsConverted)
{
  auto deck = core::readDeckFromString(R"(<ParameterList name="Capsula"><ParameterList name="Flow">
      <Parameter name="Viscosity ratio" type="int" value="5"/></ParameterList></ParameterList>)",
                                       "d");
  core::validateDeck(*deck, *validList(), "d");
  EXPECT_EQ(deck->sublist("Flow").get<double>("Viscosity ratio"), 5.0);
}

TEST(Deck, OutOfRangeValueIsNamedWithRequirement)
{
  const auto msg = errorOf(R"(<ParameterList name="Capsula"><ParameterList name="Flow">
      <Parameter name="Capillary number" type="double" value="-0.1"/></ParameterList></ParameterList>)");
  EXPECT_TRUE(contains(msg, "'Flow/Capillary number' = -0.1 is invalid: it must be a finite real number > 0")) << msg;
  const auto level = errorOf(R"(<ParameterList name="Capsula"><ParameterList name="Cells">
      <ParameterList name="Cell 0"><Parameter name="Mesh level" type="int" value="9"/></ParameterList>
      </ParameterList></ParameterList>)");
  EXPECT_TRUE(contains(level, "'Cells/Cell 0/Mesh level' = 9 is invalid: it must be an integer from 0 to 5")) << level;
}

TEST(Deck, NonFiniteRealIsRejected)
{
  const auto msg = errorOf(R"(<ParameterList name="Capsula"><ParameterList name="Flow">
      <Parameter name="Capillary number" type="double" value="nan"/></ParameterList></ParameterList>)");
  EXPECT_TRUE(contains(msg, "'Flow/Capillary number'")) << msg;
  EXPECT_TRUE(contains(msg, "finite")) << msg;
}

TEST(Deck, BadChoiceSuggestsTheClosest)
{
  const auto msg = errorOf(R"(<ParameterList name="Capsula"><ParameterList name="Cells">
      <ParameterList name="Cell 0"><Parameter name="Membrane law" type="string" value="Skalack"/>
      </ParameterList></ParameterList></ParameterList>)");
  EXPECT_TRUE(contains(msg, "one of: NeoHookean, Skalak")) << msg;
  EXPECT_TRUE(contains(msg, "did you mean \"Skalak\"")) << msg;
}

TEST(Deck, ArrayLengthIsChecked)
{
  const auto msg = errorOf(R"xml(<ParameterList name="Capsula"><ParameterList name="Cells">
      <ParameterList name="Cell 0"><Parameter name="Center" type="Array(double)" value="{1, 2}"/>
      </ParameterList></ParameterList></ParameterList>)xml");
  EXPECT_TRUE(contains(msg, "'Cells/Cell 0/Center' has 2 entries; it must have 3")) << msg;
}

TEST(Deck, ValueGivenAsSublistIsRejected)
{
  const auto msg = errorOf(R"(<ParameterList name="Capsula"><ParameterList name="Flow">
      <ParameterList name="Capillary number"/></ParameterList></ParameterList>)");
  EXPECT_TRUE(contains(msg, "'Flow/Capillary number' must be a Parameter (value)")) << msg;
}

TEST(Deck, MalformedXmlNamesTheFile)
{
  try {
    core::readDeckFromString("<ParameterList name=\"x\"><Parameter name=", "broken.xml");
    FAIL() << "malformed XML was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "Deck 'broken.xml' is not a valid Teuchos XML parameter list")) << e.what();
  }
}

TEST(Deck, MissingFileIsAnIoErrorNamingIt)
{
  try {
    core::readDeck("/nonexistent/deck.xml");
    FAIL() << "missing file was accepted";
  } catch (const capsula::core::IoError& e) {
    EXPECT_TRUE(contains(e.what(), "'/nonexistent/deck.xml'")) << e.what();
  }
}

TEST(Deck, OverridesAreTypedByTheValidList)
{
  Teuchos::ParameterList deck("Capsula");
  const auto valid = validList();
  core::applyOverride(deck, *valid, "Flow/Capillary number=0.9");
  core::applyOverride(deck, *valid, "Cells/Cell 0/Mesh level=3");
  core::applyOverride(deck, *valid, "Cells/Cell 0/Center={1, 2.5, -3}");
  core::applyOverride(deck, *valid, "Cells/Cell 0/Fixed height=yes");
  core::applyOverride(deck, *valid, "Title=a = b"); // only the first '=' splits
  core::validateDeck(deck, *valid, "--set");
  EXPECT_EQ(deck.sublist("Flow").get<double>("Capillary number"), 0.9);
  EXPECT_EQ(deck.sublist("Cells").sublist("Cell 0").get<int>("Mesh level"), 3);
  const auto center = deck.sublist("Cells").sublist("Cell 0").get<Teuchos::Array<double>>("Center");
  ASSERT_EQ(center.size(), 3u);
  EXPECT_EQ(center[2], -3.0);
  EXPECT_TRUE(deck.sublist("Cells").sublist("Cell 0").get<bool>("Fixed height"));
  EXPECT_EQ(deck.get<std::string>("Title"), "a = b");
}

TEST(Deck, BadOverridesAreNamed)
{
  Teuchos::ParameterList deck("Capsula");
  const auto valid = validList();
  const auto messageOf = [&](const std::string& assignment) -> std::string {
    try {
      core::applyOverride(deck, *valid, assignment);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_TRUE(contains(messageOf("Flow/Capillary number=abc"), "'abc' is not a finite real number"));
  EXPECT_TRUE(contains(messageOf("Flow/Capillary number=nan"), "'nan' is not a finite real number"));
  EXPECT_TRUE(contains(messageOf("Cells/Cell 0/Mesh level=99999999999"), "is not an integer"));
  EXPECT_TRUE(contains(messageOf("Cells/Cell 0/Mesh level=2.5"), "is not an integer"));
  EXPECT_TRUE(contains(messageOf("Flow/Capilary number=1"), "Did you mean 'Flow/Capillary number'?"));
  EXPECT_TRUE(contains(messageOf("Flow"), "expected \"List/Sub/Key=value\""));
  // A --set value goes through the same validation as the deck.
  core::applyOverride(deck, *valid, "Flow/Viscosity ratio=-2");
  try {
    core::validateDeck(deck, *valid, "--set");
    FAIL() << "negative viscosity ratio accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "'Flow/Viscosity ratio' = -2 is invalid")) << e.what();
  }
}

// Teuchos alone reads "abc" as 0, "2.5" as the int 2, "0.3abc" as 0.3 and overflows
// 99999999999: each of these must stop the run, naming the key, the file and the line.
TEST(Deck, DeckFileValuesAreReadAsStrictlyAsOverrides)
{
  const auto withCell = [](const std::string& parameter) {
    return "<ParameterList name=\"Capsula\">\n<ParameterList name=\"Cells\">\n<ParameterList name=\"Cell 0\">\n" +
           parameter + "\n</ParameterList></ParameterList></ParameterList>";
  };
  const auto withFlow = [](const std::string& value) {
    return "<ParameterList name=\"Capsula\"><ParameterList name=\"Flow\">\n<Parameter name=\"Capillary number\" "
           "type=\"double\" value=\"" +
           value + "\"/></ParameterList></ParameterList>";
  };
  const struct {
    std::string xml;
    std::string expected;
  } cases[] = {
      {withFlow("abc"), "Deck 'deck.xml', line 2: 'Flow/Capillary number' = \"abc\" is not a finite real number"},
      {withFlow("0.3abc"), "'Flow/Capillary number' = \"0.3abc\" is not a finite real number"},
      {withFlow("inf"), "'Flow/Capillary number' = \"inf\" is not a finite real number"},
      {withFlow("1e-400"), "'Flow/Capillary number' = \"1e-400\" is not a finite real number"}, // underflows
      {withFlow(""), "'Flow/Capillary number' = \"\" is not a finite real number"},
      {withCell(R"xml(<Parameter name="Mesh level" type="int" value="abc"/>)xml"),
       "Deck 'deck.xml', line 4: 'Cells/Cell 0/Mesh level' = \"abc\" is not an integer"},
      {withCell(R"xml(<Parameter name="Mesh level" type="int" value="2.5"/>)xml"),
       "'Cells/Cell 0/Mesh level' = \"2.5\""},
      {withCell(R"xml(<Parameter name="Mesh level" type="int" value="99999999999"/>)xml"),
       "= \"99999999999\" is not an integer"},
      {withCell(R"xml(<Parameter name="Center" type="Array(double)" value="{a, 1.6, 0}"/>)xml"),
       "'Cells/Cell 0/Center' = \"{a, 1.6, 0}\" has element 1 = \"a\", which is not a finite real number"},
      {withCell(R"xml(<Parameter name="Center" type="Array(double)" value="{0, nan, 0}"/>)xml"),
       "has element 2 = \"nan\""},
      {withCell(R"xml(<Parameter name="Center" type="Array(double)" value="0, 1, 0"/>)xml"),
       "is not an array written as {a, b, c}"},
      {withCell(R"xml(<Parameter name="Fixed height" type="bool" value="maybe"/>)xml"),
       "'Cells/Cell 0/Fixed height' = \"maybe\" is not a boolean (true or false)"},
  };
  for (const auto& c : cases) {
    const auto msg = errorOf(c.xml);
    EXPECT_TRUE(contains(msg, c.expected)) << "expected: " << c.expected << "\ngot: " << msg;
  }
}

TEST(Deck, KeyGivenTwiceNamesBothLines)
{
  const auto msg = errorOf("<ParameterList name=\"Capsula\">\n<ParameterList name=\"Flow\">\n"
                           "<Parameter name=\"Capillary number\" type=\"double\" value=\"0.3\"/>\n"
                           "<Parameter name=\"Viscosity ratio\" type=\"double\" value=\"1\"/>\n"
                           "<Parameter name=\"Capillary number\" type=\"double\" value=\"0.5\"/>\n"
                           "</ParameterList></ParameterList>");
  EXPECT_TRUE(contains(msg, "Deck 'deck.xml': 'Flow/Capillary number' is given twice (lines 3 and 5)")) << msg;
  const auto list = errorOf("<ParameterList name=\"Capsula\">\n<ParameterList name=\"Flow\"/>\n"
                            "<ParameterList name=\"Flow\"/>\n</ParameterList>");
  EXPECT_TRUE(contains(list, "'Flow' is given twice (lines 2 and 3)")) << list;
}

// The same name in different lists, comments, '>' inside a string value and a valid value
// with surrounding blanks are all fine.
TEST(Deck, StrictReadingAcceptsWhatIsValid)
{
  auto deck = core::readDeckFromString(R"xml(<?xml version="1.0"?>
<!-- a comment with <Parameter name="Title" type="int" value="x"/> inside -->
<ParameterList name="Capsula">
  <Parameter name="Title" type="string" value="a > b"/>
  <ParameterList name="Cells">
    <ParameterList name="Cell 0"><Parameter name="Mesh level" type="int" value=" 3 "/>
      <Parameter name="Center" type="Array(double)" value="{0, 1.5e0, -2}"/></ParameterList>
    <ParameterList name="Cell 1"><Parameter name="Mesh level" type="int" value="-0"/></ParameterList>
  </ParameterList>
  <ParameterList name="Flow"><Parameter name='Capillary number' type='double' value='1e-300'/></ParameterList>
</ParameterList>)xml",
                                       "deck.xml");
  EXPECT_EQ(deck->get<std::string>("Title"), "a > b");
  EXPECT_EQ(deck->sublist("Cells").sublist("Cell 0").get<int>("Mesh level"), 3);
  EXPECT_EQ(deck->sublist("Flow").get<double>("Capillary number"), 1e-300);
}

TEST(Deck, DirectoryGivenAsDeckIsNamed)
{
  try {
    core::readDeck("/tmp");
    FAIL() << "a directory was read as a deck";
  } catch (const capsula::core::IoError& e) {
    EXPECT_TRUE(contains(e.what(), "Cannot read deck '/tmp': it is a directory")) << e.what();
  }
}

TEST(Deck, WrittenXmlReadsBackIdentically)
{
  Teuchos::ParameterList deck("Capsula");
  const auto valid = validList();
  core::applyOverride(deck, *valid, "Flow/Capillary number=0.1"); // not exactly representable
  core::applyOverride(deck, *valid, "Title=<&\"quoted\">");
  core::validateDeck(deck, *valid, "d");
  for (bool withDocs : {false, true}) {
    const std::string xml = core::deckToXml(deck, withDocs);
    auto back = core::readDeckFromString(xml, "roundtrip");
    EXPECT_EQ(back->sublist("Flow").get<double>("Capillary number"), 0.1); // exact round trip
    EXPECT_EQ(back->get<std::string>("Title"), "<&\"quoted\">");
    EXPECT_EQ(back->sublist("Cells").sublist("Cell 0").get<Teuchos::Array<double>>("Center"),
              deck.sublist("Cells").sublist("Cell 0").get<Teuchos::Array<double>>("Center"));
    core::validateDeck(*back, *valid, "roundtrip");
  }
}

TEST(Deck, DocumentedDefaultsCarryDocAndRequirement)
{
  const std::string xml = core::deckToXml(*validList(), true);
  EXPECT_TRUE(contains(xml, "<!-- Ca = mu k a / G Must be a finite real number > 0. -->")) << xml;
  EXPECT_TRUE(contains(xml, "<Parameter name=\"Capillary number\" type=\"double\" value=\"0.3\"/>")) << xml;
  EXPECT_TRUE(contains(xml, "Must be one of: NeoHookean, Skalak.")) << xml;
}

TEST(Deck, DeclaringADefaultOutsideItsOwnRangeIsAProgrammingError)
{
  Teuchos::ParameterList list;
  EXPECT_THROW(core::declareReal(list, "x", -1.0, "doc", core::greaterThan(0.0)), capsula::core::Error);
}
