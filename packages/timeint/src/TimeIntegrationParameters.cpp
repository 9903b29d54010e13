#include "capsula/timeint/TimeIntegrationParameters.hpp"

#include "capsula/core/ParameterDeclaration.hpp"

#include <utility>

namespace capsula::timeint {

void declareTimeIntegrationParameters(Teuchos::ParameterList& list, bool stabilityLimitDefault,
                                      const MethodRegistry& methods)
{
  using namespace capsula::core;
  declareReal(list, "End time", 10.0, "Time at which the run ends (in the deck's time unit).");
  std::string doc = "The time-integration method.";
  for (const auto& name : methods.names()) {
    doc += " " + name + ": " + methods.info(name).description;
  }
  declareChoice(list, "Method", methods.names().front(), methods.names(), doc);
  declareReal(list, "Tolerance", 1.0e-6,
              "Local error tolerance. RKF45: eps of eq 3.50 on the largest coordinate error "
              "|x5 - x4| of a step (the thesis used 1e-10 in 3D, 1e-6 in 2D). DormandPrince45: "
              "absolute tolerance of the scaled RMS error norm. cell3d and twocell3d (lengths in cell "
              "radii): at most 1% of the smallest semi-axis of any cell.",
              greaterThan(0.0));
  methods.declareKeys(list);
  declareReal(list, "Initial step", 1.0e-3, "First step size tried; the fixed step size for RK4.", greaterThan(0.0));
  declareReal(list, "Minimum step", 1.0e-12,
              "The run fails (keeping the last good state) if the controller needs a smaller "
              "step than this.",
              greaterThan(0.0));
  declareReal(list, "Maximum step", 1.0, "Largest step the controller may take.", greaterThan(0.0));
  declareBool(list, "Stability limit", stabilityLimitDefault,
              "Adaptive methods: keep every step within the explicit method's stability limit, "
              "0.8 r / rho, rho the fastest decay rate of the system (estimated by power "
              "iteration, a few extra right-hand sides every 'Stability check interval' steps) "
              "and r the method's real stability boundary (3.02 for RKF45). Without it a loose "
              "'Tolerance' lets the error control accept steps on which an elastic membrane's "
              "fastest mode grows, and the membrane folds. Method Auto always uses it: in cell3d "
              "and twocell3d (default true) a deck's false is refused with Auto.");
  declareInt(list, "Stability check interval", 10,
             "Accepted steps between two estimates of the fastest decay rate (the first is made "
             "at the first step, and again after anything moves the nodes between steps).",
             1);
  declareReal(list, "Steady tolerance", 0.0,
              "Stop when the state stops moving: the 'Steady criterion' measure of an accepted "
              "step falls below this (0: never stop early).",
              atLeast(0.0));
  declareChoice(list, "Steady criterion", "MaxChangeRate", {"MaxChangeRate", "L2Change"},
                "MaxChangeRate: largest coordinate change of a step divided by the step size. "
                "L2Change: Euclidean norm of the change of the state over a step (the thesis's "
                "2D criterion with tolerance 1e-7; it depends on the step size and node count).");
}

TimeIntegrationSettings timeIntegrationSettings(const Teuchos::ParameterList& list, const MethodRegistry& methods)
{
  TimeIntegrationSettings s;
  s.endTime = list.get<double>("End time");
  s.method = list.get<std::string>("Method");
  s.tolerance = list.get<double>("Tolerance");
  s.initialStep = list.get<double>("Initial step");
  s.minimumStep = list.get<double>("Minimum step");
  s.maximumStep = list.get<double>("Maximum step");
  s.stabilityLimit = list.get<bool>("Stability limit");
  s.stabilityInterval = list.get<int>("Stability check interval");
  s.steadyTolerance = list.get<double>("Steady tolerance");
  s.steadyCriterion = s.steadyTolerance > 0.0
                          ? steadyStateCriterionFromString(list.get<std::string>("Steady criterion"))
                          : SteadyStateCriterion::Off;
  Teuchos::ParameterList owned("Time integration");
  methods.declareKeys(owned);
  for (auto it = owned.begin(); it != owned.end(); ++it) {
    if (list.isParameter(owned.name(it))) {
      s.methodParameters.setEntry(owned.name(it), list.getEntry(owned.name(it)));
    }
  }
  return s;
}

TimeIntegrator makeTimeIntegrator(const Teuchos::ParameterList& list, RightHandSide rhs, const MethodRegistry& methods)
{
  return TimeIntegrator(timeIntegrationSettings(list, methods), std::move(rhs), methods);
}

} // namespace capsula::timeint
