#include "capsula/run/SuspensionApplication.hpp"

#include "capsula/run/SceneApplication.hpp"
#include "capsula/run/SceneRunDeck.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/suspension/SuspensionDeck.hpp>
#include <capsula/suspension/SuspensionParameters.hpp>

#include <ostream>

namespace capsula::run {

Teuchos::RCP<const Teuchos::ParameterList> validSuspensionRunParameters(const Teuchos::ParameterList& deck,
                                                                        const std::string& appName,
                                                                        const SceneLibraries& libraries)
{
  // No 'Cells/Cell k' of its own: a raw deck's come from the placement (a deck that gives
  // some is refused there, naming them); a placed deck's are declared from its names.
  auto valid = Teuchos::rcp_const_cast<Teuchos::ParameterList>(
      validSceneRunParameters(deck, appName, libraries, /*cellsWhenNoneGiven=*/0));
  suspension::declareSuspensionParameters(*valid, deck, libraries.membraneLaws);
  // A suspension run measures the suspension unless the deck says otherwise.
  Teuchos::ParameterEntry& enabled = valid->sublist("Output").sublist("Suspension").getEntry("Enabled");
  enabled.setValue(true, false, enabled.docString(), enabled.validator());
  return valid;
}

Teuchos::ParameterList placedSceneDeck(const Teuchos::ParameterList& deck, const std::string& appName,
                                       const SceneLibraries& libraries, std::ostream* log)
{
  suspension::PlacedSuspension placed = suspension::placeSuspension(deck);
  if (log != nullptr) {
    *log << "Placed " << suspension::describePlacement(placed) << " (seed "
         << deck.sublist("Suspension").get<int>("Seed") << ")\n";
  }
  Teuchos::ParameterList& output = placed.deck.sublist("Output").sublist("Suspension");
  if (output.get<std::string>("Hematocrit type").empty()) {
    output.set("Hematocrit type", placed.fillingType); // the red cells (empty without them: every cell)
  }
  const auto valid = validSuspensionRunParameters(placed.deck, appName, libraries);
  core::validateDeck(placed.deck, *valid, "the placed suspension");
  return placed.deck;
}

int runSuspensionApplication(int argc, char** argv, const core::AppDescription& app, const SceneLibraries& libraries)
{
  const std::string name = app.name;
  const auto run = [name, &libraries](core::RunContext& context) {
    runSceneOfCommandLine(placedSceneDeck(*context.deck, name, libraries, context.out), context, name, libraries);
  };
  return core::runApplication(
      argc, argv, app,
      [name, &libraries](const Teuchos::ParameterList& deck) {
        return validSuspensionRunParameters(deck, name, libraries);
      },
      run);
}

} // namespace capsula::run
