#pragma once
// The suspension app's deck and run: the scene deck of cell3d and twocell3d
// (SceneRunDeck.hpp) without cells of its own, plus the 'Suspension' sublist
// (suspension/SuspensionParameters.hpp), whose cells are placed at the start of every run
// and restart (suspension/SuspensionDeck.hpp, seeded, so a restart places the same cells)
// and then run as any scene (runScene). 'Output/Suspension/Enabled' is true by default.
#include <capsula/core/Application.hpp>
#include <capsula/run/SceneLibraries.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>

namespace capsula::run {

/// The complete valid parameter list of a suspension deck `deck` (raw or placed), named
/// `appName`, with the kernels, summation back-ends, membrane laws and time methods of
/// `libraries`.
Teuchos::RCP<const Teuchos::ParameterList> validSuspensionRunParameters(const Teuchos::ParameterList& deck,
                                                                        const std::string& appName,
                                                                        const SceneLibraries& libraries);

/// The validated scene deck of the validated suspension deck `deck`: its cells placed and
/// written as 'Cells/Cell k', validated again (defaults filled in). `log` (may be null)
/// receives the placement's line.
Teuchos::ParameterList placedSceneDeck(const Teuchos::ParameterList& deck, const std::string& appName,
                                       const SceneLibraries& libraries, std::ostream* log);

/// The exit status of the whole program (core::runApplication) for the suspension app.
int runSuspensionApplication(int argc, char** argv, const core::AppDescription& app,
                             const SceneLibraries& libraries = standardSceneLibraries());

} // namespace capsula::run
