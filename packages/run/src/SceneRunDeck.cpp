#include "capsula/run/SceneRunDeck.hpp"

#include "capsula/run/SceneOutputSettings.hpp"

#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/scene/SceneParameters.hpp>
#include <capsula/scene/StiffSolverParameters.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>

namespace capsula::run {

Teuchos::RCP<const Teuchos::ParameterList> validSceneRunParameters(const Teuchos::ParameterList& deck,
                                                                   const std::string& appName, int cellsWhenNoneGiven)
{
  return validSceneRunParameters(deck, appName, standardSceneLibraries(), cellsWhenNoneGiven);
}

Teuchos::RCP<const Teuchos::ParameterList> validSceneRunParameters(const Teuchos::ParameterList& deck,
                                                                   const std::string& appName,
                                                                   const OperatorLibraries& libraries,
                                                                   int cellsWhenNoneGiven)
{
  return validSceneRunParameters(deck, appName, sceneLibrariesWith(libraries), cellsWhenNoneGiven);
}

Teuchos::RCP<const Teuchos::ParameterList> validSceneRunParameters(const Teuchos::ParameterList& deck,
                                                                   const std::string& appName,
                                                                   const SceneLibraries& libraries,
                                                                   int cellsWhenNoneGiven)
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList(appName));
  scene::declareSceneParameters(*valid, deck, cellsWhenNoneGiven, libraries.membraneLaws);
  timeint::declareTimeIntegrationParameters(
      core::declareSublist(*valid, "Time integration", "Time stepping (Section 3.10; docs/stiff-integration.md)."),
      /*stabilityLimitDefault=*/true, libraries.timeMethods);
  operators::declareOperatorParameters(*valid);
  declareOperatorLibraryParameters(*valid, libraries.operators);
  scene::declareStiffSolverParameters(core::declareSublist(
      valid->sublist("Solver"), "Stiff",
      "The linear solves of the stiff time integrators (Time integration/Method ROS34PW2, ROS2, Auto)."));
  scene::declareMeshEvolutionParameters(*valid);
  declareSceneOutputParameters(core::declareSublist(*valid, "Output", "What is written, where and when."));
  return valid;
}

} // namespace capsula::run
