// A program's own membrane law and time-integration method, registered in its
// SceneLibraries, are choices of the deck ('Cells/Cell k/Membrane law', 'Time
// integration/Method') and run through runScene as the built-in ones do; the standard
// libraries refuse the same deck naming the keys.
#include "SceneRunFixture.hpp"

#include "HookeanMembraneLaw.hpp"
#include "TwoStageMethod.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/run/SceneLibraries.hpp>
#include <capsula/run/SceneRun.hpp>
#include <capsula/run/SceneRunDeck.hpp>
#include <capsula/testing/InputErrorMessage.hpp>

#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

// The file's own names, apart from those of the files compiled with it.
namespace capsula::run::scene_plugins_test {
namespace {

using capsula::testing::inputErrorMessage;

SceneLibraries librariesWithOwnLawAndMethod()
{
  SceneLibraries libraries = standardSceneLibraries();
  scene::testing::registerHookeanMembraneLaw(libraries.membraneLaws);
  timeint::testing::registerTwoStageMethod(libraries.timeMethods);
  return libraries;
}

// A level-1 sphere in free shear with the program's law (nu_s = 0.3) and method, two fixed
// steps of 0.02.
Teuchos::RCP<Teuchos::ParameterList> deckWithOwnLawAndMethod()
{
  auto deck = scene::testing::sphereDeck(1, 0.0, false);
  Teuchos::ParameterList& cell = deck->sublist("Cells").sublist("Cell 0");
  cell.set("Membrane law", std::string("Hookean"));
  cell.set("Poisson ratio", 0.3);
  Teuchos::ParameterList& time = deck->sublist("Time integration");
  time.set("Method", std::string("TwoStage"));
  time.set("End time", 0.04);
  time.set("Initial step", 0.02);
  deck->sublist("Output").set("Interval", 0.02);
  return deck;
}

bool anyTermContains(const std::vector<std::string>& terms, const std::string& text)
{
  return std::any_of(terms.begin(), terms.end(),
                     [&](const std::string& term) { return term.find(text) != std::string::npos; });
}

class ScenePlugIns : public testing::SceneRunFixture {};

TEST_F(ScenePlugIns, ARunTakesTheLawAndTheMethodOfTheProgramsLibraries)
{
  const SceneLibraries libraries = librariesWithOwnLawAndMethod();
  auto deck = deckWithOwnLawAndMethod();
  core::validateDeck(*deck, *validSceneRunParameters(*deck, "test", libraries), "test deck");

  SceneRunOptions options;
  options.application = "test";
  options.outputDirectory = (root_ / "own").string();
  const SceneRunResult result =
      runScene(*deck, Tpetra::getDefaultComm(), options, kernelsForDeck(libraries.operators, *deck),
               libraries.membraneLaws, libraries.timeMethods);
  EXPECT_EQ(result.status, "finished");
  // TwoStage takes fixed steps of 'Initial step': exactly two to t = 0.04.
  EXPECT_EQ(result.acceptedSteps, 2);
  EXPECT_TRUE(anyTermContains(result.terms, "time integration: TwoStage (alpha = 1)"));
  EXPECT_TRUE(anyTermContains(result.terms, "membrane Cells/Cell 0: Hookean (Poisson ratio = 0.3)"));
}

TEST_F(ScenePlugIns, TheStandardLibrariesRefuseTheLawAndTheMethodTheyDoNotHold)
{
  const SceneLibraries standard = standardSceneLibraries();
  auto withLaw = deckWithOwnLawAndMethod();
  withLaw->sublist("Time integration").set("Method", std::string("RKF45"));
  withLaw->sublist("Cells").sublist("Cell 0").remove("Poisson ratio");
  const std::string law = inputErrorMessage(
      [&] { core::validateDeck(*withLaw, *validSceneRunParameters(*withLaw, "test", standard), "test deck"); });
  EXPECT_NE(law.find("Membrane law"), std::string::npos) << law;
  EXPECT_NE(law.find("Hookean"), std::string::npos) << law;

  auto withMethod = scene::testing::sphereDeck(1, 0.0, false);
  withMethod->sublist("Time integration").set("Method", std::string("TwoStage"));
  const std::string method = inputErrorMessage(
      [&] { core::validateDeck(*withMethod, *validSceneRunParameters(*withMethod, "test", standard), "test deck"); });
  EXPECT_NE(method.find("Method"), std::string::npos) << method;
  EXPECT_NE(method.find("TwoStage"), std::string::npos) << method;
}

} // namespace
} // namespace capsula::run::scene_plugins_test
