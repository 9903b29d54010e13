#include "capsula/timeint/TimeIntegrator.hpp"

#include "StepMessages.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/timeint/VectorNorms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace capsula::timeint {

namespace {

/// out_i = y_i + h * sum_{j < count} w_j k_j,i, skipping zero weights (so a FSAL method's
/// last stage state and its new solution, which differ only by a zero weight, agree bit
/// for bit).
inline void combineStages(const double* y, double h, const double* w, const std::vector<std::vector<double>>& k,
                          int count, double* out, std::size_t n)
{
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0.0;
    for (int j = 0; j < count; ++j) {
      if (w[j] != 0.0) {
        sum += w[j] * k[static_cast<std::size_t>(j)][i];
      }
    }
    out[i] = y[i] + h * sum;
  }
}

/// e_i = h * sum_j d_j k_j,i.
inline void errorEstimate(double h, const double* d, const std::vector<std::vector<double>>& k, int count, double* e,
                          std::size_t n)
{
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0.0;
    for (int j = 0; j < count; ++j) {
      if (d[j] != 0.0) {
        sum += d[j] * k[static_cast<std::size_t>(j)][i];
      }
    }
    e[i] = h * sum;
  }
}

using detail::shown;
using detail::stretchFraction;

// The explicit tableau: the deck's, and for Auto the thesis's RKF45 of its explicit phases
// (the stiff methods never use it).
ButcherTableau tableauFor(const TimeIntegrationSettings& s)
{
  switch (s.method) {
  case Method::RKF45:
    return s.localExtrapolation ? rungeKuttaFehlberg45Extrapolated() : rungeKuttaFehlberg45();
  case Method::DormandPrince45:
    return dormandPrince45();
  case Method::RK4:
    return classicalRungeKutta4();
  case Method::ROS34PW2:
  case Method::ROS2:
  case Method::Auto:
    break;
  }
  return rungeKuttaFehlberg45();
}

RosenbrockTableau rosenbrockFor(const TimeIntegrationSettings& s)
{
  return s.method == Method::ROS2 ? ros2() : ros34pw2();
}

// Gustafsson's PI controller for an error estimate of order k: the exponents 0.7/k and
// 0.4/k of Hairer & Wanner (Solving ODEs II, IV.8, eq 8.21 with a PI memory), a growth
// limited to 5x per step as in their stiff codes.
PiControllerParameters rosenbrockControllerFor(const RosenbrockTableau& t)
{
  PiControllerParameters p;
  const double k = t.errorEstimateOrder();
  p.alpha = 0.7 / k;
  p.beta = 0.4 / k;
  p.maximumFactor = 5.0;
  return p;
}

TimeIntegrationSettings checked(TimeIntegrationSettings s)
{
  using core::InputError;
  using core::require;
  const auto finitePositive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require<InputError>(finitePositive(s.tolerance), "Time integration/Tolerance must be a real number > 0, got ",
                      s.tolerance, ".");
  require<InputError>(std::isfinite(s.relativeTolerance) && s.relativeTolerance >= 0.0,
                      "Time integration/Relative tolerance must be a real number >= 0, got ", s.relativeTolerance, ".");
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
  require<InputError>(!s.localExtrapolation || s.method == Method::RKF45,
                      "Time integration/Local extrapolation applies to Method RKF45 only (Method is ",
                      toString(s.method), "): set it to false.");
  require<InputError>(std::isfinite(s.linearTolerance) && s.linearTolerance > 0.0 && s.linearTolerance <= 1.0,
                      "Time integration/Linear tolerance must lie in (0, 1], got ", s.linearTolerance, ".");
  require<InputError>(std::isfinite(s.switchMargin) && s.switchMargin >= 1.0,
                      "Time integration/Switch margin must be >= 1, got ", s.switchMargin, ".");
  require<InputError>(s.switchSteps >= 1, "Time integration/Switch steps must be >= 1, got ", s.switchSteps, ".");
  if (s.method == Method::RK4) {
    s.adaptive = false;
  }
  if (s.method == Method::Auto) {
    // Auto judges stiffness by the stability limit of its explicit phases.
    require<InputError>(s.adaptive, "internal: Method Auto needs adaptive steps");
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

TimeIntegrator::TimeIntegrator(TimeIntegrationSettings settings, RightHandSide rhs)
    : settings_(checked(std::move(settings))),
      rhs_(std::move(rhs)),
      tableau_(tableauFor(settings_)),
      rosenbrock_(rosenbrockFor(settings_)),
      thesisController_(settings_.tolerance),
      piController_(tableau_.hasErrorEstimate() ? tableau_.errorEstimateOrder() : 1, settings_.piController),
      rosenbrockController_(rosenbrock_.errorEstimateOrder(), rosenbrockControllerFor(rosenbrock_))
{
  core::require<core::InputError>(static_cast<bool>(rhs_), "internal: the time integrator needs a right-hand side");
  if (tableau_.hasErrorEstimate()) {
    for (int j = 0; j < tableau_.stages; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      errorWeights_.push_back(tableau_.b[jj] - tableau_.bEmbedded[jj]);
    }
  }
  core::require(!settings_.adaptive || tableau_.hasErrorEstimate(), "internal: ", tableau_.name,
                " has no error estimate");
  stabilityBoundary_ = realStabilityBoundary(tableau_);
  core::require<core::InputError>(settings_.stabilityInterval >= 1,
                                  "'Time integration/Stability check interval' = ", settings_.stabilityInterval,
                                  " must be at least 1");
}

void TimeIntegrator::setStageConstraint(StageConstraint constraint)
{
  constraint_ = std::move(constraint);
}

void TimeIntegrator::setLinearisedSystem(std::shared_ptr<LinearisedSystem> system)
{
  system_ = std::move(system);
}

bool TimeIntegrator::usesStiffMethod(const IntegrationState& state) const
{
  return settings_.method == Method::ROS34PW2 || settings_.method == Method::ROS2 ||
         (settings_.method == Method::Auto && state.stiffActive);
}

std::string TimeIntegrator::activeMethodName(const IntegrationState& state) const
{
  return usesStiffMethod(state) ? rosenbrock_.name : tableau_.name;
}

void TimeIntegrator::setDomainCheck(DomainCheck check)
{
  domainCheck_ = std::move(check);
}

bool TimeIntegrator::adaptive() const
{
  return settings_.adaptive;
}

IntegrationState TimeIntegrator::start(double t0, std::vector<double> y0) const
{
  IntegrationState s;
  s.time = t0;
  s.y = std::move(y0);
  s.proposedStep = settings_.initialStep;
  s.previousErrorNorm = settings_.piController.errorFloor;
  s.outputOrigin = t0;
  s.nextOutput = 0;
  const std::size_t bad = firstNonFinite(s.y.data(), s.y.size());
  core::require<core::NumericalError>(bad == s.y.size(), "Time integration: the initial state is not finite (entry ",
                                      bad, " of ", s.y.size(), ") at t = ", t0, ".");
  return s;
}

void TimeIntegrator::evaluate(double t, const std::vector<double>& y, std::vector<double>& dydt,
                              IntegrationState& state, double step, int stage)
{
  const std::size_t n = y.size();
  dydt.resize(n);
  rhs_(t, y, dydt);
  ++state.statistics.rhsEvaluations;
  core::require(dydt.size() == n, "internal: the right-hand side resized its output from ", n, " to ", dydt.size(),
                " entries");
  if (constraint_) {
    constraint_(t, y, dydt);
  }
  const std::size_t bad = firstNonFinite(dydt.data(), n);
  if (bad != n) {
    throw core::NumericalError(
        core::message("Time integration failed: the right-hand side is not finite at t = ", shown(t), " (entry ", bad,
                      " of ", n, " is ", dydt[bad], "; stage ", stage + 1, " of the ", activeMethodName(state),
                      " step from t = ", shown(state.time), " with dt = ", shown(step),
                      "). The state at t = ", shown(state.time), " is the last accepted one."));
  }
}

StepReport TimeIntegrator::step(IntegrationState& state, double tStop)
{
  core::require(tStop > state.time, "internal: TimeIntegrator::step needs tStop (", tStop, ") > t (", state.time, ")");
  core::require<core::InputError>(!needsLinearisedSystem(settings_.method) || system_, "Time integration/Method ",
                                  toString(settings_.method),
                                  " needs the Jacobian of the system (a LinearisedSystem), which this model "
                                  "does not provide: use an explicit method (RKF45, DormandPrince45, RK4).");
  // On failure the state is the last accepted one: restore the controller's proposal too.
  const double proposedBefore = state.proposedStep;
  const bool stiffBefore = state.stiffActive;
  const std::int64_t heldBefore = state.stiffnessHeldSteps;
  const std::int64_t failedBefore = state.stiffTrialsFailed;
  try {
    StepReport report;
    if (settings_.method == Method::Auto && state.stiffActive) {
      reconsiderExplicitMethod(state, report); // may hand this step back to RKF45
    } else if (settings_.method == Method::Auto && tryStiffMethod(state, tStop, report)) {
      return report; // the trial step of ROS34PW2 was accepted
    }
    const std::string reason = report.switchReason;
    report = usesStiffMethod(state) ? attemptLinearlyImplicit(state, tStop) : attemptUntilAccepted(state, tStop);
    report.switchReason = reason;
    if (settings_.method == Method::Auto && !report.stiff) {
      countStabilityHolds(state, report);
    }
    return report;
  } catch (...) {
    state.proposedStep = proposedBefore;
    state.stiffActive = stiffBefore;
    state.stiffnessHeldSteps = heldBefore;
    state.stiffTrialsFailed = failedBefore;
    throw;
  }
}

StepReport TimeIntegrator::attemptUntilAccepted(IntegrationState& state, double tStop)
{
  const std::size_t n = state.y.size();
  const int stages = tableau_.stages;
  slopes_.resize(static_cast<std::size_t>(stages));
  stageState_.resize(n);
  newState_.resize(n);
  errorVector_.resize(n);
  IntegrationStatistics& stats = state.statistics;

  // Stage 1 is f(t_n, y_n): the same for every attempt, and known already for FSAL.
  if (tableau_.firstSameAsLast && state.firstStageDerivative.size() == n) {
    slopes_[0] = state.firstStageDerivative;
  } else {
    evaluate(state.time, state.y, slopes_[0], state, state.proposedStep, 0);
  }
  const bool limited = settings_.adaptive && settings_.stabilityLimit; // always for Auto
  if (limited &&
      (state.stabilityVector.size() != n || state.stepsSinceStabilityEstimate >= settings_.stabilityInterval)) {
    estimateStabilityStep(state);
  }

  StepReport report;
  for (;;) {
    double proposed = settings_.adaptive ? std::min(state.proposedStep, settings_.maximumStep) : state.proposedStep;
    if (limited) {
      proposed = std::min(proposed, state.stabilityStep);
    }
    double h = proposed;
    double tNew = state.time + h;
    if (tStop - state.time <= proposed * (1.0 + stretchFraction)) {
      h = tStop - state.time;
      tNew = tStop; // exactly, whatever the rounding of time + h
    }
    report.shortened = h < proposed;
    report.heldByStabilityLimit = limited && proposed == state.stabilityStep;

    std::string outside; // why a stage state or the result left the model's domain, or ""
    try {
      for (int i = 1; i < stages; ++i) {
        combineStages(state.y.data(), h, &tableau_.a[static_cast<std::size_t>(i * stages)], slopes_, i,
                      stageState_.data(), n);
        if (domainCheck_) {
          domainCheck_(stageState_);
        }
        const double ci = tableau_.c[static_cast<std::size_t>(i)];
        const double ti = ci == 1.0 ? tNew : state.time + ci * h;
        evaluate(ti, stageState_, slopes_[static_cast<std::size_t>(i)], state, h, i);
      }
      combineStages(state.y.data(), h, tableau_.b.data(), slopes_, stages, newState_.data(), n);
      detail::requireFiniteNewState(newState_, tNew, tableau_.name, state.time, h);
      if (domainCheck_) {
        domainCheck_(newState_);
      }
    } catch (const StateOutsideDomain& e) {
      outside = e.what();
    }
    if (!outside.empty()) {
      core::require<core::NumericalError>(settings_.adaptive, "Time integration failed: ", outside, " in the fixed ",
                                          tableau_.name, " step from t = ", shown(state.time), " (dt = ", shown(h),
                                          "); use a smaller 'Time integration/Initial step'. The state at t = ",
                                          shown(state.time), " is the last accepted one.");
      ++report.rejectedAttempts;
      ++stats.rejectedSteps;
      ++stats.rejectedOutsideDomain;
      state.proposedStep = 0.5 * h;
      core::require<core::NumericalError>(state.proposedStep >= settings_.minimumStep,
                                          "Time integration failed: ", outside, " at t = ", shown(state.time),
                                          " for every step down to ", shown(h),
                                          " (below that: 'Time integration/Minimum step' = ", settings_.minimumStep,
                                          "). The state at t = ", shown(state.time), " is the last accepted one.");
      continue;
    }

    StepDecision decision{true, proposed};
    double errorNorm = 0.0;
    if (settings_.adaptive) {
      errorEstimate(h, errorWeights_.data(), slopes_, stages, errorVector_.data(), n);
      if (settings_.method == Method::DormandPrince45) {
        errorNorm = scaledRmsNorm(errorVector_.data(), state.y.data(), newState_.data(), n, settings_.tolerance,
                                  settings_.relativeTolerance);
        decision = piController_.decide(h, errorNorm, state.previousErrorNorm, report.rejectedAttempts > 0);
      } else {
        errorNorm = maxNorm(errorVector_.data(), n); // eq 3.50's |x5 - x4|
        decision = thesisController_.decide(h, errorNorm, report.rejectedAttempts > 0);
      }
    }

    if (!decision.accepted) {
      ++report.rejectedAttempts;
      ++stats.rejectedSteps;
      state.proposedStep = decision.nextStep;
      if (state.proposedStep < settings_.minimumStep) {
        throw core::NumericalError(
            core::message("Time integration failed: the step size collapsed to ", shown(state.proposedStep),
                          " (below Time integration/Minimum step = ", settings_.minimumStep,
                          ") at t = ", shown(state.time), " after ", report.rejectedAttempts,
                          report.rejectedAttempts == 1 ? " rejected attempt" : " rejected attempts",
                          " (last error estimate ", errorNorm, ", ", tableau_.name, " tolerance ", settings_.tolerance,
                          "). The state at t = ", shown(state.time),
                          " is the last accepted one. The right-hand side may be non-smooth there, or the "
                          "tolerance too tight for round-off."));
      }
      continue;
    }

    // Accepted.
    report.stepSize = h;
    report.errorNorm = errorNorm;
    if (settings_.steadyCriterion != SteadyStateCriterion::Off) {
      report.steadyMeasure = steadyStateMeasure(settings_.steadyCriterion, state.y.data(), newState_.data(), n, h);
      report.steady = report.steadyMeasure < settings_.steadyTolerance;
    }
    ++stats.acceptedSteps;
    if (limited) {
      ++state.stepsSinceStabilityEstimate;
    }
    stats.smallestStep = std::min(stats.smallestStep, h);
    stats.largestStep = std::max(stats.largestStep, h);
    stats.lastStep = h;
    stats.lastErrorNorm = errorNorm;

    state.y.swap(newState_);
    state.time = tNew;
    if (tableau_.firstSameAsLast) {
      state.firstStageDerivative.swap(slopes_[static_cast<std::size_t>(stages - 1)]);
    } else {
      state.firstStageDerivative.clear();
    }
    state.steady = report.steady;
    // A step adjusted to land on tStop says little about the step size wanted elsewhere:
    // keep the proposal it was cut from, and the PI memory.
    if (!report.shortened) {
      state.proposedStep = settings_.adaptive ? std::min(decision.nextStep, settings_.maximumStep) : decision.nextStep;
      if (settings_.adaptive && settings_.method == Method::DormandPrince45) {
        state.previousErrorNorm = piController_.rememberedError(errorNorm);
      }
    } else {
      state.proposedStep = proposed;
    }
    return report;
  }
}

} // namespace capsula::timeint
