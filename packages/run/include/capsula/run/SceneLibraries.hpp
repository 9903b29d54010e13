#pragma once
// Everything a 3D scene application lets the deck choose by name: the operator libraries
// (Green's functions, 'Operator/Kernel', and far-field back-ends, 'Operator/Summation'),
// the membrane laws ('Cells/Cell k/Membrane law') and the time-integration methods
// ('Time integration/Method'). The application owns them; a program with a law, a method
// or a kernel of its own registers it here before it declares its deck, and the deck, its
// validation, --print-defaults and the run all see it (docs/extending.md).
#include <capsula/elasticity/MembraneLawRegistry.hpp>
#include <capsula/run/OperatorLibraries.hpp>
#include <capsula/timeint/MethodRegistry.hpp>

namespace capsula::run {

struct SceneLibraries {
  OperatorLibraries operators;
  elasticity::MembraneLawRegistry membraneLaws;
  timeint::MethodRegistry timeMethods;
};

/// What cell3d and twocell3d offer: standardOperatorLibraries(), the built-in membrane
/// laws and the built-in time-integration methods.
SceneLibraries standardSceneLibraries();

/// The built-in laws and methods beside the operator libraries `operators`.
SceneLibraries sceneLibrariesWith(OperatorLibraries operators);

} // namespace capsula::run
