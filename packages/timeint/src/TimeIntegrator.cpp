// The integrator's settings and its step: the checks common to every method, and the
// step of the method the settings name, with the state restored on failure. The time loop
// is TimeLoop.cpp; the methods are plug-ins (MethodRegistry.hpp).
#include "capsula/timeint/TimeIntegrator.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/timeint/VectorNorms.hpp"

#include <cmath>
#include <utility>

namespace capsula::timeint {

namespace {

TimeIntegrationSettings checked(TimeIntegrationSettings s, const MethodTraits& traits)
{
  using core::InputError;
  using core::require;
  const auto finitePositive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require<InputError>(finitePositive(s.tolerance), "Time integration/Tolerance must be a real number > 0, got ",
                      s.tolerance, ".");
  require<InputError>(finitePositive(s.initialStep), "Time integration/Initial step must be > 0, got ", s.initialStep,
                      ".");
  require<InputError>(finitePositive(s.minimumStep), "Time integration/Minimum step must be > 0, got ", s.minimumStep,
                      ".");
  require<InputError>(finitePositive(s.maximumStep), "Time integration/Maximum step must be > 0, got ", s.maximumStep,
                      ".");
  require<InputError>(finitePositive(s.endTime), "Time integration/End time must be > 0 (runs start at t = 0), got ",
                      s.endTime, ".");
  require<InputError>(std::isfinite(s.steadyTolerance) && s.steadyTolerance >= 0.0,
                      "Time integration/Steady tolerance must be >= 0 (0 = off), got ", s.steadyTolerance, ".");
  require<InputError>(s.stabilityInterval >= 1, "'Time integration/Stability check interval' = ", s.stabilityInterval,
                      " must be at least 1");
  if (traits.fixedSteps) {
    s.adaptive = false;
  }
  if (traits.stabilityLimit) {
    // The method judges stiffness by the stability limit of its explicit phases.
    require<InputError>(s.adaptive, "internal: Method ", s.method, " needs adaptive steps");
    s.stabilityLimit = true;
  }
  if (s.adaptive) {
    require<InputError>(s.minimumStep <= s.initialStep && s.initialStep <= s.maximumStep,
                        "Time integration: need Minimum step <= Initial step <= Maximum step, got ", s.minimumStep,
                        ", ", s.initialStep, ", ", s.maximumStep,
                        ". Change Time integration/Initial step or the bounds.");
  }
  if (s.steadyTolerance == 0.0) {
    s.steadyCriterion = SteadyStateCriterion::Off;
  }
  return s;
}

} // namespace

TimeIntegrator::TimeIntegrator(TimeIntegrationSettings settings, RightHandSide rhs, const MethodRegistry& methods)
    : traits_(methods.info(settings.method).traits),
      context_(checked(std::move(settings), traits_), std::move(rhs)),
      method_(methods.create(context_.settings()))
{}

void TimeIntegrator::setStageConstraint(StageConstraint constraint)
{
  context_.setStageConstraint(std::move(constraint));
}

void TimeIntegrator::setLinearisedSystem(std::shared_ptr<LinearisedSystem> system)
{
  context_.setLinearisedSystem(std::move(system));
}

void TimeIntegrator::setDomainCheck(DomainCheck check)
{
  context_.setDomainCheck(std::move(check));
}

bool TimeIntegrator::adaptive() const
{
  return settings().adaptive;
}

std::string TimeIntegrator::activeMethodName(const IntegrationState& state) const
{
  return method_->activeMethodName(state);
}

std::string TimeIntegrator::describe() const
{
  return method_->describe(settings());
}

IntegrationState TimeIntegrator::start(double t0, std::vector<double> y0) const
{
  IntegrationState s;
  s.time = t0;
  s.y = std::move(y0);
  s.proposedStep = settings().initialStep;
  s.previousErrorNorm = settings().piController.errorFloor;
  s.outputOrigin = t0;
  s.nextOutput = 0;
  const std::size_t bad = firstNonFinite(s.y.data(), s.y.size());
  core::require<core::NumericalError>(bad == s.y.size(), "Time integration: the initial state is not finite (entry ",
                                      bad, " of ", s.y.size(), ") at t = ", t0, ".");
  return s;
}

StepReport TimeIntegrator::step(IntegrationState& state, double tStop)
{
  core::require(tStop > state.time, "internal: TimeIntegrator::step needs tStop (", tStop, ") > t (", state.time, ")");
  core::require<core::InputError>(!traits_.linearisedSystem || hasLinearisedSystem(), "Time integration/Method ",
                                  settings().method,
                                  " needs the Jacobian of the system (a LinearisedSystem), which this model "
                                  "does not provide: use an explicit method (RKF45, DormandPrince45, RK4).");
  // On failure the state is the last accepted one: restore the controller's proposal and
  // a switching method's bookkeeping too.
  const double proposedBefore = state.proposedStep;
  const bool stiffBefore = state.stiffActive;
  const std::int64_t heldBefore = state.stiffnessHeldSteps;
  const std::int64_t failedBefore = state.stiffTrialsFailed;
  try {
    return method_->step(context_, state, tStop);
  } catch (...) {
    state.proposedStep = proposedBefore;
    state.stiffActive = stiffBefore;
    state.stiffnessHeldSteps = heldBefore;
    state.stiffTrialsFailed = failedBefore;
    throw;
  }
}

} // namespace capsula::timeint
