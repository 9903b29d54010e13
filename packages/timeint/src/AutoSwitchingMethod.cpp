// Method Auto (AutoSwitchingMethod): RKF45 with the stability limit while the membrane is soft, ROS34PW2 while
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
#include "AutoSwitchingMethod.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace capsula::timeint::detail {

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

AutoSwitchingMethod::AutoSwitchingMethod(const TimeIntegrationSettings& settings, double relativeTolerance,
                                         double linearTolerance, double switchMargin, int switchSteps)
    : explicit_(settings, false),
      stiff_(ros34pw2(), relativeTolerance, linearTolerance),
      switchMargin_(switchMargin),
      switchSteps_(switchSteps)
{}

std::string AutoSwitchingMethod::activeMethodName(const IntegrationState& state) const
{
  return state.stiffActive ? stiff_.activeMethodName(state) : explicit_.activeMethodName(state);
}

std::string AutoSwitchingMethod::describe(const TimeIntegrationSettings& s) const
{
  std::ostringstream line;
  line << "time integration: " << s.method << ": " << explicit_.tableau().name << " with the stability limit; after "
       << switchSteps_ << " steps held by the limit, " << stiff_.activeMethodName({}) << " if a trial step "
       << switchMargin_
       << " x (the cost of a stiff step over that of an explicit one) times the limit meets half the tolerance, "
       << "and back when " << explicit_.tableau().name << " advances " << switchMargin_
       << " x further per operator application; tolerance " << s.tolerance;
  return line.str();
}

StepReport AutoSwitchingMethod::step(StepContext& context, IntegrationState& state, double tStop)
{
  StepReport report;
  if (state.stiffActive) {
    reconsiderExplicitMethod(context, state, report); // may hand this step back to RKF45
  } else if (tryStiffMethod(context, state, tStop, report)) {
    return report; // the trial step of ROS34PW2 was accepted
  }
  const std::string reason = report.switchReason;
  report = state.stiffActive ? stiff_.attempt(context, state, tStop, 0.0) : explicit_.step(context, state, tStop);
  report.switchReason = reason;
  if (!report.stiff) {
    state.stiffnessHeldSteps = report.heldByStabilityLimit ? state.stiffnessHeldSteps + 1 : 0;
  }
  return report;
}

double AutoSwitchingMethod::stiffStepCost(const IntegrationState& state)
{
  const IntegrationStatistics& s = state.statistics;
  if (s.stiffSteps == 0) {
    return assumedStiffStepCost;
  }
  return static_cast<double>(s.stiffRhsEvaluations + s.linearIterations + s.linearisations) /
         static_cast<double>(s.stiffSteps);
}

bool AutoSwitchingMethod::tryStiffMethod(StepContext& context, IntegrationState& state, double tStop,
                                         StepReport& report)
{
  const TimeIntegrationSettings& settings = context.settings();
  const std::int64_t needed = switchSteps_ * (std::int64_t{1} << std::min(state.stiffTrialsFailed, maximumBackOff));
  if (state.stiffnessHeldSteps < needed) {
    return false;
  }
  const double limit = state.stabilityStep;
  const double trialStep = switchMargin_ * stiffStepCost(state) / explicit_.stepCost(settings) * limit;
  if (!(trialStep <= settings.maximumStep) || trialStep > tStop - state.time) {
    return false; // no room for the trial before the next output: keep counting
  }
  state.stiffnessHeldSteps = 0;
  const double previousError = state.previousErrorNorm;
  const double proposedBefore = state.proposedStep;
  state.previousErrorNorm = settings.piController.errorFloor;
  StepReport trial = stiff_.attempt(context, state, tStop, trialStep);
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
  why << "switched to " << stiff_.activeMethodName(state) << ": the stability limit held " << explicit_.tableau().name
      << " at dt = " << limit << " for " << needed << " steps, and a trial step of " << stiff_.activeMethodName(state)
      << " of dt = " << trialStep << " (" << trialStep / limit << " times that) met the tolerance (error "
      << trial.errorNorm << " of it)";
  trial.switchReason = why.str();
  report = trial;
  return true;
}

void AutoSwitchingMethod::reconsiderExplicitMethod(StepContext& context, IntegrationState& state, StepReport& report)
{
  const TimeIntegrationSettings& settings = context.settings();
  const std::size_t n = state.y.size();
  if (state.stabilityVector.size() == n && state.stepsSinceStabilityEstimate < settings.stabilityInterval) {
    return;
  }
  explicit_.estimateStabilityLimit(context, state);
  const double stiffStep = std::min(state.proposedStep, settings.maximumStep);
  const double explicitStep = std::min(state.stabilityStep, stiffStep);
  const double gain = (explicitStep / explicit_.stepCost(settings)) / (stiffStep / stiffStepCost(state));
  if (!(gain > switchMargin_)) {
    return;
  }
  state.stiffActive = false;
  state.stiffnessHeldSteps = 0;
  ++state.stiffTrialsFailed;
  ++state.statistics.methodSwitches;
  state.proposedStep = explicitStep;
  std::ostringstream why;
  why.precision(3);
  why << "switched to " << explicit_.tableau().name << ": its stability limit allows dt = " << state.stabilityStep
      << " against " << stiff_.activeMethodName(state) << "'s " << stiffStep << "; " << explicit_.tableau().name
      << " is expected to advance " << gain << " times further per operator application";
  report.switchReason = why.str();
}

} // namespace capsula::timeint::detail
