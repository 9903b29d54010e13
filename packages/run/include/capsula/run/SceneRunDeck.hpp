#pragma once
// The deck of the 3D scene apps (cell3d, twocell3d), assembled from the declarations of the
// components that read each sublist:
//   Flow, Wall, Cells          scene/SceneParameters.hpp
//   Time integration           timeint/TimeIntegrationParameters.hpp
//   Discretisation, Solver     operators/OperatorParameters.hpp
//   Operator                   OperatorLibraries.hpp (the registries' kernels and back-ends)
//   Mesh regularisation, Mesh adaption   scene/SceneParameters.hpp (capsula::mesh)
//   Output                     SceneOutputSettings.hpp
#include <capsula/run/OperatorLibraries.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>

namespace capsula::run {

/// The complete valid parameter list for `deck` (one "Cells/Cell k" sublist for every one
/// the deck has, `cellsWhenNoneGiven` for a deck without cells), named `appName`, with
/// the kernels and summation back-ends of `libraries`.
Teuchos::RCP<const Teuchos::ParameterList> validSceneRunParameters(const Teuchos::ParameterList& deck,
                                                                   const std::string& appName,
                                                                   const OperatorLibraries& libraries,
                                                                   int cellsWhenNoneGiven = 1);

/// The same with standardOperatorLibraries().
Teuchos::RCP<const Teuchos::ParameterList>
validSceneRunParameters(const Teuchos::ParameterList& deck, const std::string& appName, int cellsWhenNoneGiven = 1);

} // namespace capsula::run
