#pragma once
// The deck's "Time integration" sublist:
//
//   <ParameterList name="Time integration">
//     <Parameter name="End time" type="double" value="20"/>
//     <Parameter name="Method" type="string" value="RKF45"/>   a name in the MethodRegistry
//     <Parameter name="Tolerance" type="double" value="1e-6"/>
//     ...
//   </ParameterList>
//
// The keys common to every method are declared here; each method declares the keys it owns
// (MethodRegistry.hpp), and the doc string of 'Method' is made of the methods' descriptions.
//
// Default tolerance 1e-6: the thesis used eps = 1e-6 for its 2D runs (App. A.8) and
// 1e-10 for 3D (Section 3.10). Positions are in cell radii, so 1e-6 is a local error of a
// millionth of a radius per step, far below the spatial discretisation error of the
// meshes used; thesis-reproduction decks set 1e-10 explicitly.
#include "capsula/timeint/MethodRegistry.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::timeint {

/// Declares the keys of the "Time integration" sublist in `list` (the sublist itself):
/// the common ones, 'Method' with the names of `methods`, and the keys of every method.
/// `stabilityLimitDefault`: the default of "Stability limit" (on for the 3D capsule apps,
/// whose membranes make the system stiff; off where an app has not been measured with it).
void declareTimeIntegrationParameters(Teuchos::ParameterList& list, bool stabilityLimitDefault = false,
                                      const MethodRegistry& methods = builtInMethods());

/// Settings from a validated "Time integration" sublist; the keys of every method in
/// `methods` that the list holds go to methodParameters.
TimeIntegrationSettings timeIntegrationSettings(const Teuchos::ParameterList& list,
                                                const MethodRegistry& methods = builtInMethods());

/// The integrator a validated "Time integration" sublist describes, with its method from
/// `methods`. Throws core::InputError naming the key if the values are inconsistent.
TimeIntegrator makeTimeIntegrator(const Teuchos::ParameterList& list, RightHandSide rhs,
                                  const MethodRegistry& methods = builtInMethods());

} // namespace capsula::timeint
