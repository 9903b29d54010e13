#include "capsula/run/SceneApplication.hpp"

#include "capsula/run/OperatorLibraries.hpp"
#include "capsula/run/SceneLibraries.hpp"
#include "capsula/run/SceneRunDeck.hpp"
#include "capsula/run/SceneRun.hpp"

#include <string>

namespace capsula::run {

void runSceneOfCommandLine(const Teuchos::ParameterList& deck, const core::RunContext& context,
                           const std::string& application, const SceneLibraries& libraries)
{
  SceneRunOptions options;
  options.application = application;
  options.deckSource = context.deckName;
  options.outputDirectory = context.options.outputDirectory;
  options.restartDirectory = context.options.restartDirectory;
  options.log = context.out;
  runScene(deck, context.comm, options, kernelsForDeck(libraries.operators, deck), libraries.membraneLaws,
           libraries.timeMethods);
}

int runSceneApplication(int argc, char** argv, const core::AppDescription& app, int cellsWhenNoneGiven)
{
  return runSceneApplication(argc, argv, app, standardSceneLibraries(), cellsWhenNoneGiven);
}

int runSceneApplication(int argc, char** argv, const core::AppDescription& app, const OperatorLibraries& libraries,
                        int cellsWhenNoneGiven)
{
  return runSceneApplication(argc, argv, app, sceneLibrariesWith(libraries), cellsWhenNoneGiven);
}

int runSceneApplication(int argc, char** argv, const core::AppDescription& app, const SceneLibraries& libraries,
                        int cellsWhenNoneGiven)
{
  const std::string name = app.name;
  const auto run = [name, &libraries](core::RunContext& context) {
    runSceneOfCommandLine(*context.deck, context, name, libraries);
  };
  return core::runApplication(
      argc, argv, app,
      [name, cellsWhenNoneGiven, &libraries](const Teuchos::ParameterList& deck) {
        return validSceneRunParameters(deck, name, libraries, cellsWhenNoneGiven);
      },
      run);
}

} // namespace capsula::run
