// Method Auto: RKF45 with the stability limit while the membrane is soft, ROS34PW2 while
// it is stiff. Work is counted in operator applications (a right-hand side, a Krylov
// iteration or a linearisation each count one), never in seconds, so the decisions, and
// with them the run, are the same on any machine and any number of ranks, and a restart
// repeats them.
//
//   explicit -> stiff: the stability limit bound RKF45's step for `switchSteps` consecutive
//     steps: the step is set by stiffness, not accuracy. ROS34PW2 takes over unless it was
//     tried before and advanced less simulated time per application than RKF45 does now
//     at this limit (by the margin).
//   stiff -> explicit: every `stabilityInterval` stiff steps the explicit limit h_e is
//     estimated again; RKF45 takes over if it would advance further per application, by
//     the margin: min(h_e, h) / (cost of an explicit step) > switchMargin * h / (cost of a
//     stiff step), h the stiff method's step (RKF45's accuracy-limited step is taken to be
//     no larger than the stiff method's). The stiff method's rate is remembered for the
//     next forward decision.
//
// An explicit error estimate cannot say how far accuracy alone would let the step grow:
// at the stability limit the stiff modes dominate it.
#include "capsula/timeint/TimeIntegrator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace capsula::timeint {

namespace {

// Operator applications of a stiff step before any has been measured: four stages, each
// one right-hand side and about eight Krylov iterations, plus the linearisation.
constexpr double assumedStiffStepCost = 37.0;

// The first stiff step tries this multiple of the explicit limit; the stiff method's
// controller takes it from there (it grows the step at most 5-fold per step).
constexpr double firstStiffStepFactor = 10.0;

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

void TimeIntegrator::reconsiderStiffMethod(IntegrationState& state, StepReport& report)
{
  if (!report.heldByStabilityLimit) {
    state.stiffnessHeldSteps = 0;
    return;
  }
  if (++state.stiffnessHeldSteps < settings_.switchSteps) {
    return;
  }
  state.stiffnessHeldSteps = 0;
  const double h = report.stepSize;
  const double explicitRate = h / explicitStepCost();
  if (state.stiffAdvanceRate > 0.0 && !(state.stiffAdvanceRate > settings_.switchMargin * explicitRate)) {
    return;   // tried, and not worth it at this limit
  }
  state.stiffActive = true;
  ++state.statistics.methodSwitches;
  state.proposedStep = std::min(settings_.maximumStep, firstStiffStepFactor * h);
  state.previousErrorNorm = settings_.piController.errorFloor;
  std::ostringstream why;
  why.precision(3);
  why << "switched to " << rosenbrock_.name << ": for " << settings_.switchSteps << " steps the stability limit held "
      << tableau_.name << " at dt = " << h;
  if (state.stiffAdvanceRate > 0.0) {
    why << "; " << rosenbrock_.name << " advanced " << state.stiffAdvanceRate / explicitRate
        << " times further per operator application when last used";
  }
  report.switchReason = why.str();
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
  const double stiffRate = stiffStep / stiffStepCost(state);
  const double gain = (explicitStep / explicitStepCost()) / stiffRate;
  if (!(gain > settings_.switchMargin)) {
    return;
  }
  state.stiffActive = false;
  state.stiffnessHeldSteps = 0;
  state.stiffAdvanceRate = stiffRate;
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
