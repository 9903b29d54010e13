#pragma once
// The deck's "Time integration" sublist:
//
//   <ParameterList name="Time integration">
//     <Parameter name="End time" type="double" value="20"/>
//     <Parameter name="Method" type="string" value="RKF45"/>   RKF45 | DormandPrince45 | RK4
//     <Parameter name="Tolerance" type="double" value="1e-6"/>
//     ...
//   </ParameterList>
//
// Default tolerance 1e-6: the thesis used eps = 1e-6 for its 2D runs (App. A.8) and
// 1e-10 for 3D (Section 3.10). Positions are in cell radii, so 1e-6 is a local error of a
// millionth of a radius per step, far below the spatial discretisation error of the
// meshes used; thesis-reproduction decks set 1e-10 explicitly.
#include "capsula/timeint/TimeIntegrator.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::timeint {

/// Declares the keys of the "Time integration" sublist in `list` (the sublist itself).
/// `stabilityLimitDefault`: the default of "Stability limit" (on for the 3D capsule apps,
/// whose membranes make the system stiff; off where an app has not been measured with it).
void declareTimeIntegrationParameters(Teuchos::ParameterList& list, bool stabilityLimitDefault = false);

/// Settings from a validated "Time integration" sublist.
TimeIntegrationSettings timeIntegrationSettings(const Teuchos::ParameterList& list);

/// One line for a run's "Terms built": the method, its tolerance and what limits its steps.
std::string describeTimeIntegration(const TimeIntegrationSettings& settings);

/// The integrator a validated "Time integration" sublist describes. Throws
/// core::InputError naming the key if the values are inconsistent.
TimeIntegrator makeTimeIntegrator(const Teuchos::ParameterList& list, RightHandSide rhs);

} // namespace capsula::timeint
