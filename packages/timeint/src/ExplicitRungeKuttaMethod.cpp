// The step of an explicit Runge-Kutta method: stages, error estimate, stability limit,
// rejection and retry.
#include "ExplicitRungeKuttaMethod.hpp"

#include "StepMessages.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"
#include "capsula/timeint/VectorNorms.hpp"

#include <algorithm>
#include <sstream>
#include <utility>

namespace capsula::timeint::detail {

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

} // namespace

ExplicitRungeKuttaMethod::ExplicitRungeKuttaMethod(ButcherTableau tableau, const TimeIntegrationSettings& settings)
    : tableau_(std::move(tableau)), stabilityBoundary_(realStabilityBoundary(tableau_))
{
  if (tableau_.hasErrorEstimate()) {
    for (int j = 0; j < tableau_.stages; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      errorWeights_.push_back(tableau_.b[jj] - tableau_.bEmbedded[jj]);
    }
  }
  core::require(!settings.adaptive || tableau_.hasErrorEstimate(), "internal: ", tableau_.name,
                " has no error estimate");
}

std::string ExplicitRungeKuttaMethod::activeMethodName(const IntegrationState&) const
{
  return tableau_.name;
}

std::string ExplicitRungeKuttaMethod::describe(const TimeIntegrationSettings& s) const
{
  std::ostringstream line;
  line << "time integration: " << s.method;
  if (!tableau_.hasErrorEstimate()) {
    line << ", fixed steps of " << s.initialStep;
    return line.str();
  }
  line << ", tolerance " << s.tolerance << (s.stabilityLimit ? ", stability limit" : "");
  return line.str();
}

double ExplicitRungeKuttaMethod::stepCost(const TimeIntegrationSettings& settings) const
{
  return tableau_.stages + 3.0 / settings.stabilityInterval;
}

void ExplicitRungeKuttaMethod::estimateStabilityLimit(StepContext& context, IntegrationState& state)
{
  slopes_.resize(std::max<std::size_t>(slopes_.size(), 1));
  context.evaluate(state.time, state.y, slopes_[0], state, state.proposedStep, 0, tableau_.name);
  context.estimateStabilityStep(state, slopes_[0], stabilityBoundary_, tableau_.name);
}

double ExplicitRungeKuttaMethod::errorNorm(const std::vector<double>&, const IntegrationState&,
                                           const std::vector<double>&) const
{
  throw core::Error("internal: " + tableau_.name + " has no error control");
}

StepDecision ExplicitRungeKuttaMethod::decide(double, double, const IntegrationState&, bool) const
{
  throw core::Error("internal: " + tableau_.name + " has no step-size controller");
}

void ExplicitRungeKuttaMethod::remember(IntegrationState&, double) const {}

void ExplicitRungeKuttaMethod::computeStages(StepContext& context, IntegrationState& state, double h, double tNew)
{
  const std::size_t n = state.y.size();
  const int stages = tableau_.stages;
  for (int i = 1; i < stages; ++i) {
    combineStages(state.y.data(), h, &tableau_.a[static_cast<std::size_t>(i * stages)], slopes_, i, stageState_.data(),
                  n);
    context.checkDomain(stageState_);
    const double ci = tableau_.c[static_cast<std::size_t>(i)];
    const double ti = ci == 1.0 ? tNew : state.time + ci * h;
    context.evaluate(ti, stageState_, slopes_[static_cast<std::size_t>(i)], state, h, i, tableau_.name);
  }
  combineStages(state.y.data(), h, tableau_.b.data(), slopes_, stages, newState_.data(), n);
  requireFiniteNewState(newState_, tNew, tableau_.name, state.time, h);
  context.checkDomain(newState_);
}

StepReport ExplicitRungeKuttaMethod::step(StepContext& context, IntegrationState& state, double tStop)
{
  const TimeIntegrationSettings& settings = context.settings();
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
    context.evaluate(state.time, state.y, slopes_[0], state, state.proposedStep, 0, tableau_.name);
  }
  const bool limited = settings.adaptive && settings.stabilityLimit;
  if (limited &&
      (state.stabilityVector.size() != n || state.stepsSinceStabilityEstimate >= settings.stabilityInterval)) {
    context.estimateStabilityStep(state, slopes_[0], stabilityBoundary_, tableau_.name);
  }

  StepReport report;
  for (;;) {
    double proposed = settings.adaptive ? std::min(state.proposedStep, settings.maximumStep) : state.proposedStep;
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
      computeStages(context, state, h, tNew);
    } catch (const StateOutsideDomain& e) {
      outside = e.what();
    }
    if (!outside.empty()) {
      core::require<core::NumericalError>(settings.adaptive, "Time integration failed: ", outside, " in the fixed ",
                                          tableau_.name, " step from t = ", shown(state.time), " (dt = ", shown(h),
                                          "); use a smaller 'Time integration/Initial step'. The state at t = ",
                                          shown(state.time), " is the last accepted one.");
      ++report.rejectedAttempts;
      ++stats.rejectedSteps;
      ++stats.rejectedOutsideDomain;
      state.proposedStep = 0.5 * h;
      core::require<core::NumericalError>(state.proposedStep >= settings.minimumStep,
                                          "Time integration failed: ", outside, " at t = ", shown(state.time),
                                          " for every step down to ", shown(h),
                                          " (below that: 'Time integration/Minimum step' = ", settings.minimumStep,
                                          "). The state at t = ", shown(state.time), " is the last accepted one.");
      continue;
    }

    StepDecision decision{true, proposed};
    double norm = 0.0;
    if (settings.adaptive) {
      errorEstimate(h, errorWeights_.data(), slopes_, stages, errorVector_.data(), n);
      norm = errorNorm(errorVector_, state, newState_);
      decision = decide(h, norm, state, report.rejectedAttempts > 0);
    }

    if (!decision.accepted) {
      ++report.rejectedAttempts;
      ++stats.rejectedSteps;
      state.proposedStep = decision.nextStep;
      if (state.proposedStep < settings.minimumStep) {
        throw core::NumericalError(core::message(
            "Time integration failed: the step size collapsed to ", shown(state.proposedStep),
            " (below Time integration/Minimum step = ", settings.minimumStep, ") at t = ", shown(state.time), " after ",
            report.rejectedAttempts, report.rejectedAttempts == 1 ? " rejected attempt" : " rejected attempts",
            " (last error estimate ", norm, ", ", tableau_.name, " tolerance ", settings.tolerance,
            "). The state at t = ", shown(state.time),
            " is the last accepted one. The right-hand side may be non-smooth there, or the "
            "tolerance too tight for round-off."));
      }
      continue;
    }

    context.recordAcceptedStep(state, report, h, tNew, norm, newState_);
    if (limited) {
      ++state.stepsSinceStabilityEstimate;
    }
    if (tableau_.firstSameAsLast) {
      state.firstStageDerivative.swap(slopes_[static_cast<std::size_t>(stages - 1)]);
    } else {
      state.firstStageDerivative.clear();
    }
    if (context.proposeNextStep(state, report, proposed, decision.nextStep)) {
      remember(state, norm);
    }
    return report;
  }
}

} // namespace capsula::timeint::detail
