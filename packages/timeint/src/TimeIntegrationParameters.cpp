#include "capsula/timeint/TimeIntegrationParameters.hpp"

#include "capsula/core/ParameterDeclaration.hpp"

#include <sstream>
#include <utility>

namespace capsula::timeint {

void declareTimeIntegrationParameters(Teuchos::ParameterList& list, bool stabilityLimitDefault)
{
  using namespace capsula::core;
  declareReal(list, "End time", 10.0, "Time at which the run ends (in the deck's time unit).");
  std::vector<std::string> methods;
  for (const Method m : allMethods()) {
    methods.push_back(toString(m));
  }
  declareChoice(list, "Method", "RKF45", methods,
                "RKF45: the thesis's Runge-Kutta-Fehlberg with its step doubling/halving (eqs "
                "3.47-3.50). DormandPrince45: 5th order with a smooth PI step-size controller. "
                "RK4: classical Runge-Kutta with fixed steps of 'Initial step'. ROS34PW2: a "
                "linearly implicit Rosenbrock-W method of order 3 (L-stable) for stiff membranes: "
                "its step is limited by accuracy only, each stage solving a linear system with "
                "the flow operator and the membrane's tangent stiffness (the 'Solver/Stiff' "
                "settings). ROS2: the same idea at order 2. Auto: RKF45 with the stability limit "
                "while the membrane is soft, ROS34PW2 while the stability limit holds the step "
                "well below what accuracy allows (docs/stiff-integration.md).");
  declareReal(list, "Tolerance", 1.0e-6,
              "Local error tolerance. RKF45: eps of eq 3.50 on the largest coordinate error "
              "|x5 - x4| of a step (the thesis used 1e-10 in 3D, 1e-6 in 2D). DormandPrince45: "
              "absolute tolerance of the scaled RMS error norm. cell3d and twocell3d (lengths in cell "
              "radii): at most 1% of the smallest semi-axis of any cell.",
              greaterThan(0.0));
  declareReal(list, "Relative tolerance", 0.0,
              "DormandPrince45 only: relative tolerance added to 'Tolerance' in the error "
              "scale (0: purely absolute, as positions have no natural scale).",
              atLeast(0.0));
  declareBool(list, "Local extrapolation", false,
              "RKF45 only: advance with the 5th-order solution instead of the thesis's 4th.");
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
  declareReal(list, "Linear tolerance", 0.01,
              "ROS34PW2, ROS2, Auto: each stage's linear solve stops when its RMS residual falls "
              "below this fraction of 'Tolerance' (the solve's error then stays below the local "
              "error the step is allowed).",
              greaterThan(0.0), atMost(1.0));
  declareReal(list, "Auto switch margin", 2.0,
              "Auto: change method only when the other one is expected to advance at least this "
              "many times further per operator application (work counted in right-hand sides and "
              "Krylov iterations).",
              atLeast(1.0));
  declareInt(list, "Auto switch steps", 5,
             "Auto: consecutive explicit steps the stability limit must hold before the stiff "
             "method takes over.",
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

TimeIntegrationSettings timeIntegrationSettings(const Teuchos::ParameterList& list)
{
  TimeIntegrationSettings s;
  s.endTime = list.get<double>("End time");
  s.method = methodFromString(list.get<std::string>("Method"));
  s.adaptive = s.method != Method::RK4;
  s.tolerance = list.get<double>("Tolerance");
  s.relativeTolerance = list.get<double>("Relative tolerance");
  s.localExtrapolation = list.get<bool>("Local extrapolation");
  s.initialStep = list.get<double>("Initial step");
  s.minimumStep = list.get<double>("Minimum step");
  s.maximumStep = list.get<double>("Maximum step");
  s.stabilityLimit = list.get<bool>("Stability limit");
  s.stabilityInterval = list.get<int>("Stability check interval");
  s.linearTolerance = list.get<double>("Linear tolerance");
  s.switchMargin = list.get<double>("Auto switch margin");
  s.switchSteps = list.get<int>("Auto switch steps");
  s.steadyTolerance = list.get<double>("Steady tolerance");
  s.steadyCriterion = s.steadyTolerance > 0.0
                          ? steadyStateCriterionFromString(list.get<std::string>("Steady criterion"))
                          : SteadyStateCriterion::Off;
  return s;
}

std::string describeTimeIntegration(const TimeIntegrationSettings& s)
{
  std::ostringstream line;
  line << "time integration: " << toString(s.method);
  switch (s.method) {
  case Method::RK4:
    line << ", fixed steps of " << s.initialStep;
    return line.str();
  case Method::ROS34PW2:
  case Method::ROS2:
    line << " (Rosenbrock-W, order " << (s.method == Method::ROS2 ? 2 : 3) << ", L-stable), tolerance " << s.tolerance
         << "; stage solves to " << s.linearTolerance << " x tolerance";
    return line.str();
  case Method::Auto:
    line << ": RKF45 with the stability limit; after " << s.switchSteps
         << " steps held by the limit, ROS34PW2 if a trial step " << s.switchMargin
         << " x (the cost of a stiff step over that of an explicit one) times the limit meets half the tolerance, "
         << "and back when RKF45 advances " << s.switchMargin << " x further per operator application; tolerance "
         << s.tolerance;
    return line.str();
  case Method::RKF45:
  case Method::DormandPrince45:
    break;
  }
  line << ", tolerance " << s.tolerance << (s.stabilityLimit ? ", stability limit" : "");
  return line.str();
}

TimeIntegrator makeTimeIntegrator(const Teuchos::ParameterList& list, RightHandSide rhs)
{
  return TimeIntegrator(timeIntegrationSettings(list), std::move(rhs));
}

} // namespace capsula::timeint
