// Method Auto: RKF45 with the stability limit while the membrane is soft, ROS34PW2 while
// it is stiff. Work is counted in operator applications (a right-hand side, a Krylov
// iteration or a linearisation each count one), never in seconds, so the decisions, and
// with them the run, are the same on any machine and any number of ranks, and a restart
// repeats them.
//
//   explicit -> stiff: once the stability limit has bound RKF45's step for `switchSteps`
//     consecutive steps (times 2^k after k failed trials), ROS34PW2 tries one step of
//       h_trial = switchMargin * (cost of a stiff step / cost of an explicit step) * h_limit,
//     the smallest step with which it advances further per application than RKF45 by the
//     margin. If that step meets half the tolerance, it is kept and ROS34PW2 goes on; if it
//     meets only the tolerance, the step is kept and RKF45 goes on; if it fails, the state
//     is left as it was and RKF45 takes the step. An explicit error estimate cannot tell
//     in advance: at the stability limit the stiff modes dominate it.
//   stiff -> explicit: every `stabilityInterval` stiff steps the explicit limit h_e is
//     estimated again; RKF45 takes over if it would advance further per application, by
//     the margin: min(h_e, h) / (cost of an explicit step) > switchMargin * h / (cost of a
//     stiff step), h the stiff method's step (RKF45's accuracy-limited step is taken to be
//     no larger than the stiff method's). This also counts as a failed trial.
#include "capsula/timeint/TimeIntegrator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace capsula::timeint {

namespace {

// Operator applications of a stiff step before any has been measured: four stages, each
// one right-hand side and about three Krylov iterations, and the linearisation (measured
// on capsules at level 2: 10-18).
constexpr double assumedStiffStepCost = 17.0;

// At most 2^this times switchSteps held steps between trials.
constexpr std::int64_t maximumBackOff = 16;

// A trial step convinces only with an error estimate of at most this fraction of the
// tolerance: with errors ~h^3 the stiff method could then go on with steps 1.26 times as
// large, so the trial did not just catch a moment where the solution happens to be smooth.
// (The soft demo capsule passes its trial steps at 0.96 and 1.9-3.4 of the tolerance, the
// stiff Goldman capsules at 0.01-0.6.)
constexpr double trialErrorBound = 0.5;

} // namespace

double TimeIntegrator::explicitStepCost() const
{
  // The explicit tableau's stages, and the power iteration's three right-hand sides every
  // stabilityInterval steps.
  return tableau_.stages + 3.0 / settings_.stabilityInterval;
}

double TimeIntegrator::stiffStepCost(const IntegrationState& state) const
{
  const IntegrationStatistics& s = state.statistics;
  if (s.stiffSteps == 0) {
    return assumedStiffStepCost;
  }
  return static_cast<double>(s.stiffRhsEvaluations + s.linearIterations + s.linearisations) /
         static_cast<double>(s.stiffSteps);
}

void TimeIntegrator::countStabilityHolds(IntegrationState& state, const StepReport& report) const
{
  state.stiffnessHeldSteps = report.heldByStabilityLimit ? state.stiffnessHeldSteps + 1 : 0;
}

bool TimeIntegrator::tryStiffMethod(IntegrationState& state, double tStop, StepReport& report)
{
  const std::int64_t needed =
      settings_.switchSteps * (std::int64_t{1} << std::min(state.stiffTrialsFailed, maximumBackOff));
  if (state.stiffnessHeldSteps < needed) {
    return false;
  }
  const double limit = state.stabilityStep;
  const double trialStep = settings_.switchMargin * stiffStepCost(state) / explicitStepCost() * limit;
  if (!(trialStep <= settings_.maximumStep) || trialStep > tStop - state.time) {
    return false; // no room for the trial before the next output: keep counting
  }
  state.stiffnessHeldSteps = 0;
  const double previousError = state.previousErrorNorm;
  const double proposedBefore = state.proposedStep;
  state.previousErrorNorm = settings_.piController.errorFloor;
  StepReport trial = attemptLinearlyImplicit(state, tStop, trialStep);
  if (trial.stepSize > 0.0 && !(trial.errorNorm <= trialErrorBound)) {
    // Accepted, but at the edge of the tolerance: keep the step, not the method.
    state.stiffTrialsFailed += 1;
    state.previousErrorNorm = previousError;
    state.proposedStep = proposedBefore;
    report = trial;
    report.stiff = true;
    return true;
  }
  if (trial.stepSize == 0.0) {
    ++state.stiffTrialsFailed;
    state.previousErrorNorm = previousError;
    return false;
  }
  state.stiffActive = true;
  ++state.statistics.methodSwitches;
  std::ostringstream why;
  why.precision(3);
  why << "switched to " << rosenbrock_.name << ": the stability limit held " << tableau_.name << " at dt = " << limit
      << " for " << needed << " steps, and a trial step of " << rosenbrock_.name << " of dt = " << trialStep << " ("
      << trialStep / limit << " times that) met the tolerance (error " << trial.errorNorm << " of it)";
  trial.switchReason = why.str();
  report = trial;
  return true;
}

void TimeIntegrator::reconsiderExplicitMethod(IntegrationState& state, StepReport& report)
{
  const std::size_t n = state.y.size();
  if (state.stabilityVector.size() == n && state.stepsSinceStabilityEstimate < settings_.stabilityInterval) {
    return;
  }
  slopes_.resize(std::max<std::size_t>(slopes_.size(), 1));
  evaluate(state.time, state.y, slopes_[0], state, state.proposedStep, 0);
  estimateStabilityStep(state);
  const double stiffStep = std::min(state.proposedStep, settings_.maximumStep);
  const double explicitStep = std::min(state.stabilityStep, stiffStep);
  const double gain = (explicitStep / explicitStepCost()) / (stiffStep / stiffStepCost(state));
  if (!(gain > settings_.switchMargin)) {
    return;
  }
  state.stiffActive = false;
  state.stiffnessHeldSteps = 0;
  ++state.stiffTrialsFailed;
  ++state.statistics.methodSwitches;
  state.proposedStep = explicitStep;
  std::ostringstream why;
  why.precision(3);
  why << "switched to " << tableau_.name << ": its stability limit allows dt = " << state.stabilityStep << " against "
      << rosenbrock_.name << "'s " << stiffStep << "; " << tableau_.name << " is expected to advance " << gain
      << " times further per operator application";
  report.switchReason = why.str();
}

} // namespace capsula::timeint
