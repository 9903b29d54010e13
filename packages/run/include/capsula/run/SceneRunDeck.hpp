#pragma once
// The deck of the 3D scene apps (cell3d, twocell3d), assembled from the declarations of the
// components that read each sublist:
//   Flow, Wall, Cells          scene/SceneParameters.hpp
//   Time integration           timeint/TimeIntegrationParameters.hpp
//   Discretisation, Solver     operators/OperatorParameters.hpp
//   Operator                   OperatorLibraries.hpp (the registries' kernels and back-ends)
// with the membrane laws and time-integration methods of the SceneLibraries.
//   Mesh regularisation, Mesh adaption   scene/SceneParameters.hpp (capsula::mesh)
//   Output                     SceneOutputSettings.hpp
#include <capsula/run/OperatorLibraries.hpp>
#include <capsula/run/SceneLibraries.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>

namespace capsula::run {

/// The complete valid parameter list for `deck` (one "Cells/Cell k" sublist for every one
/// the deck has, `cellsWhenNoneGiven` for a deck without cells), named `appName`, with
/// the kernels, summation back-ends, membrane laws and time methods of `libraries`.
Teuchos::RCP<const Teuchos::ParameterList> validSceneRunParameters(const Teuchos::ParameterList& deck,
                                                                   const std::string& appName,
                                                                   const SceneLibraries& libraries,
                                                                   int cellsWhenNoneGiven = 1);

/// The same with the operator libraries `libraries` and the built-in laws and methods.
Teuchos::RCP<const Teuchos::ParameterList> validSceneRunParameters(const Teuchos::ParameterList& deck,
                                                                   const std::string& appName,
                                                                   const OperatorLibraries& libraries,
                                                                   int cellsWhenNoneGiven = 1);

/// The same with standardSceneLibraries().
Teuchos::RCP<const Teuchos::ParameterList>
validSceneRunParameters(const Teuchos::ParameterList& deck, const std::string& appName, int cellsWhenNoneGiven = 1);

} // namespace capsula::run
