// Pass-through sublists (PassThroughSublist.hpp): the deck check lets their entries through,
// --set reaches them, and their reader's check names each refused key by its full path.
#include "capsula/core/Deck.hpp"
#include "capsula/core/DeckValidators.hpp"
#include "capsula/core/Error.hpp"
#include "capsula/core/ParameterDeclaration.hpp"
#include "capsula/core/PassThroughSublist.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace core = capsula::core;

namespace {

// A "Solver" list with a declared key and the pass-through sublist "Library".
Teuchos::RCP<const Teuchos::ParameterList> validSolverList()
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("App"));
  auto& solver = core::declareSublist(*valid, "Solver", "The linear solver.");
  core::declareReal(solver, "Tolerance", 1e-9, "stopping tolerance", core::greaterThan(0.0));
  core::declarePassThroughSublist(solver, "Library", "Settings handed to the library.");
  return valid;
}

// What the library itself accepts: one key of each kind, one it validates, one a deck
// cannot hold, and a nested list.
Teuchos::ParameterList libraryParameters()
{
  Teuchos::ParameterList valid("Library");
  valid.set("Maximum Iterations", 100);
  valid.set("Convergence Tolerance", 1e-8);
  valid.set("Orthogonalization", "ICGS", "how", Teuchos::rcp(new core::ChoiceValidator({"ICGS", "DGKS"})));
  valid.set("Output Stream", Teuchos::rcpFromRef(std::cout));
  valid.sublist("Nested").set("Depth", 2);
  return valid;
}

std::string passThroughError(Teuchos::ParameterList entries)
{
  try {
    core::checkPassThroughEntries(entries, libraryParameters(), "Solver/Library", "the library 'L'");
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no error";
}

bool has(const std::string& text, const std::string& piece)
{
  return text.find(piece) != std::string::npos;
}

} // namespace

TEST(PassThroughSublist, DeckCheckLetsItsEntriesThroughAndKeepsThem)
{
  auto deck = core::readDeckFromString(R"(<ParameterList name="App">
      <ParameterList name="Solver">
        <ParameterList name="Library">
          <Parameter name="Anything at all" type="int" value="3"/>
          <ParameterList name="Nested"><Parameter name="Deeper" type="string" value="x"/></ParameterList>
        </ParameterList>
      </ParameterList>
    </ParameterList>)",
                                       "deck.xml");
  // A copy of the valid list, as --print-defaults and the apps make, keeps the marker.
  const Teuchos::ParameterList copy(*validSolverList());
  core::validateDeck(*deck, copy, "deck.xml");
  const Teuchos::ParameterList& library = deck->sublist("Solver").sublist("Library");
  EXPECT_EQ(library.get<int>("Anything at all"), 3);
  EXPECT_EQ(library.sublist("Nested").get<std::string>("Deeper"), "x");
  EXPECT_EQ(deck->sublist("Solver").get<double>("Tolerance"), 1e-9); // the declared keys still get defaults
  EXPECT_TRUE(core::isPassThroughSublist(copy.sublist("Solver").getEntry("Library")));
  EXPECT_FALSE(core::isPassThroughSublist(copy.getEntry("Solver")));
}

TEST(PassThroughSublist, DeckCheckStillRequiresASublistAndChecksItsNeighbours)
{
  const auto valid = validSolverList();
  auto value = core::readDeckFromString(R"(<ParameterList name="App"><ParameterList name="Solver">
      <Parameter name="Library" type="int" value="3"/></ParameterList></ParameterList>)",
                                        "deck.xml");
  try {
    core::validateDeck(*value, *valid, "deck.xml");
    FAIL() << "a value accepted where the pass-through sublist belongs";
  } catch (const core::InputError& e) {
    EXPECT_TRUE(has(e.what(), "'Solver/Library' must be a ParameterList (sublist)")) << e.what();
  }
  auto misspelt = core::readDeckFromString(R"(<ParameterList name="App"><ParameterList name="Solver">
      <Parameter name="Tolerence" type="double" value="1e-7"/></ParameterList></ParameterList>)",
                                           "deck.xml");
  try {
    core::validateDeck(*misspelt, *valid, "deck.xml");
    FAIL() << "a misspelt declared key accepted";
  } catch (const core::InputError& e) {
    EXPECT_TRUE(has(e.what(), "Did you mean 'Solver/Tolerance'?")) << e.what();
  }
}

TEST(PassThroughSublist, OverridesInsideItAreTypedByTheirText)
{
  const auto valid = validSolverList();
  Teuchos::ParameterList deck("App");
  core::applyOverride(deck, *valid, "Solver/Library/Maximum Iterations=40");
  core::applyOverride(deck, *valid, "Solver/Library/Convergence Tolerance=1e-7");
  core::applyOverride(deck, *valid, "Solver/Library/Flexible=true");
  core::applyOverride(deck, *valid, "Solver/Library/Orthogonalization=DGKS");
  core::applyOverride(deck, *valid, "Solver/Library/Nested/Depth=4");
  const Teuchos::ParameterList& library = deck.sublist("Solver").sublist("Library");
  EXPECT_EQ(library.get<int>("Maximum Iterations"), 40);
  EXPECT_EQ(library.get<double>("Convergence Tolerance"), 1e-7);
  EXPECT_TRUE(library.get<bool>("Flexible"));
  EXPECT_EQ(library.get<std::string>("Orthogonalization"), "DGKS");
  EXPECT_EQ(library.sublist("Nested").get<int>("Depth"), 4);
  // A key the deck already holds keeps its type: "1" stays a real.
  core::applyOverride(deck, *valid, "Solver/Library/Convergence Tolerance=1");
  EXPECT_EQ(library.get<double>("Convergence Tolerance"), 1.0);
  core::validateDeck(deck, *valid, "--set");
  // Outside it, an undeclared key is still refused.
  EXPECT_THROW(core::applyOverride(deck, *valid, "Solver/Maximum Iterations=40"), core::InputError);
}

TEST(PassThroughSublist, ReaderCheckAcceptsWhatTheLibraryTakes)
{
  Teuchos::ParameterList entries("Library");
  entries.set("Maximum Iterations", 7);
  entries.set("Convergence Tolerance", 1); // an integer where the library takes a real
  entries.set("Orthogonalization", "DGKS");
  entries.sublist("Nested").set("Depth", 3);
  core::checkPassThroughEntries(entries, libraryParameters(), "Solver/Library", "the library 'L'");
  EXPECT_TRUE(entries.isType<double>("Convergence Tolerance"));
  EXPECT_EQ(entries.get<double>("Convergence Tolerance"), 1.0);
}

TEST(PassThroughSublist, ReaderCheckNamesEachRefusedKeyByItsPath)
{
  Teuchos::ParameterList unknown;
  unknown.set("Maximum Iteration", 7);
  const std::string misspelt = passThroughError(unknown);
  EXPECT_TRUE(has(misspelt, "'Solver/Library/Maximum Iteration' is not a parameter of the library 'L'.")) << misspelt;
  EXPECT_TRUE(has(misspelt, "Did you mean 'Solver/Library/Maximum Iterations'?")) << misspelt;
  // The keys listed are those a deck can set: not the output stream.
  EXPECT_TRUE(has(misspelt, "'Maximum Iterations', 'Convergence Tolerance', 'Orthogonalization', 'Nested'."))
      << misspelt;
  Teuchos::ParameterList stream;
  stream.set("Output Stream", "cout");
  EXPECT_TRUE(has(passThroughError(stream), "'Solver/Library/Output Stream' is not a parameter"));

  Teuchos::ParameterList wrongType;
  wrongType.set("Maximum Iterations", "many");
  const std::string type = passThroughError(wrongType);
  EXPECT_TRUE(has(type, "'Solver/Library/Maximum Iterations' has type string but the library 'L' takes a int."))
      << type;

  Teuchos::ParameterList refused;
  refused.set("Orthogonalization", "Householder");
  const std::string value = passThroughError(refused);
  EXPECT_TRUE(has(value, "'Solver/Library/Orthogonalization' is refused by the library 'L': ")) << value;
  EXPECT_TRUE(has(value, "Householder")) << value;

  Teuchos::ParameterList nested;
  nested.sublist("Nested").set("Dpth", 1);
  EXPECT_TRUE(has(passThroughError(nested), "'Solver/Library/Nested/Dpth' is not a parameter"));
  Teuchos::ParameterList listForValue;
  listForValue.sublist("Maximum Iterations");
  EXPECT_TRUE(has(passThroughError(listForValue), "'Solver/Library/Maximum Iterations' must be a value"));
}

TEST(PassThroughSublist, PrintedDefaultsShowItsDocAndReadBack)
{
  const std::string xml = core::deckToXml(*validSolverList(), true);
  EXPECT_TRUE(has(xml, "<!-- Settings handed to the library. -->")) << xml;
  EXPECT_TRUE(has(xml, "<ParameterList name=\"Library\">")) << xml;
  auto back = core::readDeckFromString(xml, "defaults");
  core::validateDeck(*back, *validSolverList(), "defaults");
  EXPECT_EQ(back->sublist("Solver").sublist("Library").numParams(), 0);
}

TEST(Error, LastLineOfALibraryMessage)
{
  EXPECT_EQ(core::lastLineOf("/usr/include/x.hpp:12:\n\nThrow test: a\n\nThe sentence.\n \n"), "The sentence.");
  EXPECT_EQ(core::lastLineOf("one line"), "one line");
  EXPECT_EQ(core::lastLineOf(""), "");
}
