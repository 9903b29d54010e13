// The built-in methods with their keys (MethodRegistry.hpp): each registration says what
// the method is (for the doc string of 'Time integration/Method'), which keys it owns,
// what the integrator must know of it, and how it is built from those keys.
#include "AutoSwitchingMethod.hpp"
#include "ExplicitMethods.hpp"
#include "RosenbrockMethod.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/ParameterDeclaration.hpp"
#include "capsula/timeint/MethodRegistry.hpp"

#include <cmath>
#include <memory>

namespace capsula::timeint {

namespace {

using Keys = Teuchos::RCP<Teuchos::ParameterList>;

Keys newKeys()
{
  return Teuchos::rcp(new Teuchos::ParameterList("Time integration"));
}

// The keys of a method whose error is scaled by Tolerance + Relative tolerance |y_i|.
void declareRelativeTolerance(Teuchos::ParameterList& keys)
{
  core::declareReal(keys, "Relative tolerance", 0.0,
                    "DormandPrince45, ROS34PW2, ROS2, Auto: relative tolerance added to 'Tolerance' in the error "
                    "scale (0: purely absolute, as positions have no natural scale).",
                    core::atLeast(0.0));
}

double relativeTolerance(const Teuchos::ParameterList& keys)
{
  const double value = keys.get<double>("Relative tolerance");
  core::require<core::InputError>(std::isfinite(value) && value >= 0.0,
                                  "Time integration/Relative tolerance must be a real number >= 0, got ", value, ".");
  return value;
}

// The keys of the Rosenbrock-W methods (and of Auto, which takes its stiff steps with one).
Keys rosenbrockKeys()
{
  auto keys = newKeys();
  declareRelativeTolerance(*keys);
  core::declareReal(*keys, "Linear tolerance", 0.01,
                    "ROS34PW2, ROS2, Auto: each stage's linear solve stops when its RMS residual falls below this "
                    "fraction of 'Tolerance' (the solve's error then stays below the local error the step is "
                    "allowed).",
                    core::greaterThan(0.0), core::atMost(1.0));
  return keys;
}

double linearTolerance(const Teuchos::ParameterList& keys)
{
  const double value = keys.get<double>("Linear tolerance");
  core::require<core::InputError>(std::isfinite(value) && value > 0.0 && value <= 1.0,
                                  "Time integration/Linear tolerance must lie in (0, 1], got ", value, ".");
  return value;
}

void registerExplicitMethods(MethodRegistry& registry)
{
  auto fehlbergKeys = newKeys();
  core::declareBool(*fehlbergKeys, "Local extrapolation", false,
                    "RKF45 only: advance with the 5th-order solution instead of the thesis's 4th.");
  registry.add("RKF45",
               {"the thesis's Runge-Kutta-Fehlberg with its step doubling/halving (eqs 3.47-3.50).", fehlbergKeys,
                MethodTraits{}, [](const TimeIntegrationSettings& settings, const Teuchos::ParameterList& keys) {
                  return std::make_unique<detail::FehlbergMethod>(settings, keys.get<bool>("Local extrapolation"));
                }});
  auto dormandPrinceKeys = newKeys();
  declareRelativeTolerance(*dormandPrinceKeys);
  registry.add("DormandPrince45",
               {"5th order with a smooth PI step-size controller.", dormandPrinceKeys, MethodTraits{},
                [](const TimeIntegrationSettings& settings, const Teuchos::ParameterList& keys) {
                  return std::make_unique<detail::DormandPrinceMethod>(settings, relativeTolerance(keys));
                }});
  MethodTraits fixed;
  fixed.fixedSteps = true;
  registry.add("RK4", {"classical Runge-Kutta with fixed steps of 'Initial step'.", Teuchos::null, fixed,
                       [](const TimeIntegrationSettings& settings, const Teuchos::ParameterList&) {
                         return std::make_unique<detail::ClassicalRungeKuttaMethod>(settings);
                       }});
}

void registerStiffMethods(MethodRegistry& registry)
{
  MethodTraits stiff;
  stiff.linearisedSystem = true;
  const auto rosenbrock = [](RosenbrockTableau (*tableau)()) {
    return [tableau](const TimeIntegrationSettings&, const Teuchos::ParameterList& keys) {
      return std::make_unique<detail::RosenbrockMethod>(tableau(), relativeTolerance(keys), linearTolerance(keys));
    };
  };
  registry.add("ROS34PW2",
               {"a linearly implicit Rosenbrock-W method of order 3 (L-stable) for stiff membranes: its step is "
                "limited by accuracy only, each stage solving a linear system with the flow operator and the "
                "membrane's tangent stiffness (the 'Solver/Stiff' settings).",
                rosenbrockKeys(), stiff, rosenbrock(&ros34pw2)});
  registry.add("ROS2", {"the same idea at order 2.", rosenbrockKeys(), stiff, rosenbrock(&ros2)});

  auto autoKeys = rosenbrockKeys();
  core::declareReal(*autoKeys, "Auto switch margin", 2.0,
                    "Auto: change method only when the other one is expected to advance at least this many times "
                    "further per operator application (work counted in right-hand sides and Krylov iterations).",
                    core::atLeast(1.0));
  core::declareInt(*autoKeys, "Auto switch steps", 5,
                   "Auto: consecutive explicit steps the stability limit must hold before the stiff method takes "
                   "over.",
                   1);
  MethodTraits switching = stiff;
  switching.stabilityLimit = true;
  registry.add(
      "Auto", {"RKF45 with the stability limit while the membrane is soft, ROS34PW2 while the stability limit "
               "holds the step well below what accuracy allows (docs/stiff-integration.md).",
               autoKeys, switching, [](const TimeIntegrationSettings& settings, const Teuchos::ParameterList& keys) {
                 const double margin = keys.get<double>("Auto switch margin");
                 const int steps = keys.get<int>("Auto switch steps");
                 core::require<core::InputError>(std::isfinite(margin) && margin >= 1.0,
                                                 "Time integration/Auto switch margin must be >= 1, got ", margin, ".");
                 core::require<core::InputError>(steps >= 1, "Time integration/Auto switch steps must be >= 1, got ",
                                                 steps, ".");
                 return std::make_unique<detail::AutoSwitchingMethod>(settings, relativeTolerance(keys),
                                                                      linearTolerance(keys), margin, steps);
               }});
}

} // namespace

void registerBuiltInMethods(MethodRegistry& registry)
{
  registerExplicitMethods(registry);
  registerStiffMethods(registry);
}

MethodRegistry builtInMethods()
{
  MethodRegistry registry;
  registerBuiltInMethods(registry);
  return registry;
}

} // namespace capsula::timeint
