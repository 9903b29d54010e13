// What every method uses of the integrator: the evaluation of the right-hand side with its
// checks, the domain check and the bookkeeping of an accepted step. The stability limit's
// estimate is StabilityLimit.cpp.
#include "capsula/timeint/TimeIntegrationMethod.hpp"

#include "StepMessages.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/timeint/VectorNorms.hpp"

#include <algorithm>
#include <utility>

namespace capsula::timeint {

using detail::shown;

StepContext::StepContext(TimeIntegrationSettings settings, RightHandSide rhs)
    : settings_(std::move(settings)), rhs_(std::move(rhs))
{
  core::require<core::InputError>(static_cast<bool>(rhs_), "internal: the time integrator needs a right-hand side");
}

void StepContext::evaluate(double t, const std::vector<double>& y, std::vector<double>& dydt, IntegrationState& state,
                           double step, int stage, const std::string& method)
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
    throw core::NumericalError(core::message(
        "Time integration failed: the right-hand side is not finite at t = ", shown(t), " (entry ", bad, " of ", n,
        " is ", dydt[bad], "; stage ", stage + 1, " of the ", method, " step from t = ", shown(state.time),
        " with dt = ", shown(step), "). The state at t = ", shown(state.time), " is the last accepted one."));
  }
}

void StepContext::checkDomain(const std::vector<double>& y) const
{
  if (domainCheck_) {
    domainCheck_(y);
  }
}

void StepContext::recordAcceptedStep(IntegrationState& state, StepReport& report, double h, double tNew,
                                     double errorNorm, std::vector<double>& newState) const
{
  const std::size_t n = state.y.size();
  report.stepSize = h;
  report.errorNorm = errorNorm;
  if (settings_.steadyCriterion != SteadyStateCriterion::Off) {
    report.steadyMeasure = steadyStateMeasure(settings_.steadyCriterion, state.y.data(), newState.data(), n, h);
    report.steady = report.steadyMeasure < settings_.steadyTolerance;
  }
  IntegrationStatistics& stats = state.statistics;
  ++stats.acceptedSteps;
  stats.smallestStep = std::min(stats.smallestStep, h);
  stats.largestStep = std::max(stats.largestStep, h);
  stats.lastStep = h;
  stats.lastErrorNorm = errorNorm;
  state.y.swap(newState);
  state.time = tNew;
  state.steady = report.steady;
}

bool StepContext::proposeNextStep(IntegrationState& state, const StepReport& report, double proposed,
                                  double nextStep) const
{
  if (report.shortened) {
    state.proposedStep = proposed;
    return false;
  }
  state.proposedStep = settings_.adaptive ? std::min(nextStep, settings_.maximumStep) : nextStep;
  return settings_.adaptive;
}

} // namespace capsula::timeint
