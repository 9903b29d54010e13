#pragma once
// Deck name ('Time integration/Method') -> time-integration method, with the keys each
// method owns. The built-in methods (RKF45, DormandPrince45, RK4, ROS34PW2, ROS2, Auto)
// are registered by registerBuiltInMethods; a new method is a class implementing
// TimeIntegrationMethod, registered with its factory and its keys (docs/extending.md).
// Nothing global: whoever builds the integrator owns the registry and decides what it
// holds.
#include "capsula/timeint/TimeIntegrationMethod.hpp"

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace capsula::timeint {

/// What the integrator must know of a method before it creates it.
struct MethodTraits {
  /// The method has no error estimate: the run takes fixed steps of 'Initial step'.
  bool fixedSteps = false;
  /// The method needs the Jacobian of the system (TimeIntegrator::setLinearisedSystem).
  bool linearisedSystem = false;
  /// The method judges stiffness by the stability limit: 'Stability limit' is on.
  bool stabilityLimit = false;
};

/// Builds the method from the integrator's settings and the values of the keys it owns
/// (its MethodInfo::keys with the settings' values, defaults filled in). Throws
/// core::InputError naming the key ('Time integration/<key>') for a value it cannot use.
using MethodFactory = std::function<std::unique_ptr<TimeIntegrationMethod>(const TimeIntegrationSettings& settings,
                                                                           const Teuchos::ParameterList& keys)>;

struct MethodInfo {
  /// Sentences for the doc string of 'Time integration/Method': what the method is and
  /// when to choose it.
  std::string description;
  /// The keys the method owns, declared with default, validator and doc string
  /// (core::declareReal, ...); they become keys of the deck's "Time integration" sublist.
  /// Several methods may own the same key if they declare it alike. Null: none.
  Teuchos::RCP<const Teuchos::ParameterList> keys;
  MethodTraits traits;
  MethodFactory factory;
};

class MethodRegistry {
public:
  /// Registers `name`; throws (internal) if it is taken, or if one of its keys is owned by
  /// an earlier method with another type or default.
  void add(const std::string& name, MethodInfo info);

  bool has(const std::string& name) const;
  /// The registered names, in the order of registration (the deck's list of choices).
  const std::vector<std::string>& names() const { return names_; }
  /// Throws core::InputError naming 'Time integration/Method', the registered methods
  /// and the closest name if there is none called `name`.
  const MethodInfo& info(const std::string& name) const;

  /// The method settings.method names, built from its keys' values in
  /// settings.methodParameters (defaults filled in). Throws core::InputError naming
  /// 'Time integration/<key>' for a key that only other methods own set away from its
  /// default, or for a key no method owns.
  std::unique_ptr<TimeIntegrationMethod> create(const TimeIntegrationSettings& settings) const;

  /// Declares, in the "Time integration" sublist `list`, the keys of every method (each
  /// once, in the order of registration).
  void declareKeys(Teuchos::ParameterList& list) const;

private:
  std::vector<std::string> names_;
  std::map<std::string, MethodInfo> methods_;
};

/// Registers "RKF45", "DormandPrince45", "RK4" (explicit Runge-Kutta), "ROS34PW2", "ROS2"
/// (Rosenbrock-W) and "Auto" (RKF45 and ROS34PW2, switching), in that order.
void registerBuiltInMethods(MethodRegistry& registry);

/// A registry holding the built-in methods.
MethodRegistry builtInMethods();

} // namespace capsula::timeint
