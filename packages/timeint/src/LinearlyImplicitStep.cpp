// One accepted step of a Rosenbrock-W method (RosenbrockTableau.hpp):
//   (I - h gamma J~) u_i = h gamma f(t + alpha_i h, y + sum_{j<i} a_ij u_j) + gamma sum_{j<i} c_ij u_j,
//   y_new = y + sum_i m_i u_i,   e = sum_i (m_i - mEmbedded_i) u_i,
// J~ frozen at (t_n, y_n) by the LinearisedSystem for every attempt of the step.
#include "capsula/timeint/TimeIntegrator.hpp"

#include "StepMessages.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/timeint/VectorNorms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace capsula::timeint {

namespace {

using detail::shown;
using detail::stretchFraction;

// out = y + sum_{j < count} w_j u_j (zero weights skipped).
void combine(const std::vector<double>& y, const double* w, const std::vector<std::vector<double>>& u, int count,
             std::vector<double>& out)
{
  const std::size_t n = y.size();
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0.0;
    for (int j = 0; j < count; ++j) {
      if (w[j] != 0.0) {
        sum += w[j] * u[static_cast<std::size_t>(j)][i];
      }
    }
    out[i] = y[i] + sum;
  }
}

} // namespace

// The stages of one attempt of size h ending at tNew: the increments u_1..u_s and, if every
// solve converged, newState_. Returns why a solve did not converge ("" if all did); throws
// StateOutsideDomain for a stage state or result outside the model.
std::string TimeIntegrator::solveStages(IntegrationState& state, double h, double tNew, int& iterations)
{
  const RosenbrockTableau& R = rosenbrock_;
  const std::size_t n = state.y.size();
  const int s = R.stages;
  IntegrationStatistics& stats = state.statistics;
  const double shift = h * R.gamma;
  const double residualTarget = settings_.linearTolerance * settings_.tolerance;
  for (int i = 0; i < s; ++i) {
    const std::vector<double>* slope = &slopes_[0];
    if (i > 0) {
      combine(state.y, &R.a[static_cast<std::size_t>(i * s)], increments_, i, stageState_);
      if (domainCheck_) {
        domainCheck_(stageState_);
      }
      const double ti = state.time + R.stageTime[static_cast<std::size_t>(i)] * h;
      evaluate(ti, stageState_, probeSlope_, state, h, i);
      slope = &probeSlope_;
    }
    for (std::size_t k = 0; k < n; ++k) {
      double coupling = 0.0;
      for (int j = 0; j < i; ++j) {
        coupling += R.cCoefficient(i, j) * increments_[static_cast<std::size_t>(j)][k];
      }
      stageRhs_[k] = shift * (*slope)[k] + R.gamma * coupling;
    }
    std::vector<double>& u = increments_[static_cast<std::size_t>(i)];
    u.assign(n, 0.0);
    const LinearSolveReport solved = system_->solve(shift, stageRhs_, u, residualTarget);
    ++stats.linearSolves;
    stats.linearIterations += solved.iterations;
    stats.largestLinearIterations = std::max<std::int64_t>(stats.largestLinearIterations, solved.iterations);
    iterations += solved.iterations;
    if (!solved.converged) {
      ++stats.failedLinearSolves;
      std::ostringstream why;
      why << "the solve of stage " << i + 1 << " stopped after " << solved.iterations
          << " iterations at an RMS residual of " << solved.residualRms << " (target " << residualTarget << ")";
      return why.str();
    }
  }
  combine(state.y, R.m.data(), increments_, s, newState_);
  detail::requireFiniteNewState(newState_, tNew, R.name, state.time, h);
  if (domainCheck_) {
    domainCheck_(newState_);
  }
  return "";
}

StepReport TimeIntegrator::attemptLinearlyImplicit(IntegrationState& state, double tStop, double trialStep)
{
  const bool trial = trialStep > 0.0;
  const double proposedBefore = state.proposedStep;
  const RosenbrockTableau& R = rosenbrock_;
  const std::size_t n = state.y.size();
  const int s = R.stages;
  IntegrationStatistics& stats = state.statistics;
  if (slopes_.empty()) {
    slopes_.resize(1);
  }
  increments_.resize(static_cast<std::size_t>(s));
  stageRhs_.resize(n);
  newState_.resize(n);
  errorVector_.resize(n);

  // f(t_n, y_n) and J~ there serve every attempt of this step.
  const std::int64_t rhsBefore = stats.rhsEvaluations;
  evaluate(state.time, state.y, slopes_[0], state, state.proposedStep, 0);
  system_->linearise(state.time, state.y);
  ++stats.linearisations;
  state.firstStageDerivative.clear();

  StepReport report;
  report.stiff = true;
  std::vector<double> difference(static_cast<std::size_t>(s));
  for (int i = 0; i < s; ++i) {
    difference[static_cast<std::size_t>(i)] =
        R.m[static_cast<std::size_t>(i)] - R.mEmbedded[static_cast<std::size_t>(i)];
  }
  for (;;) {
    const double proposed = trial                ? trialStep
                            : settings_.adaptive ? std::min(state.proposedStep, settings_.maximumStep)
                                                 : state.proposedStep;
    double h = proposed;
    double tNew = state.time + h;
    if (tStop - state.time <= proposed * (1.0 + stretchFraction)) {
      h = tStop - state.time;
      tNew = tStop;
    }
    report.shortened = h < proposed;

    std::string outside, unsolved;
    int iterations = 0;
    try {
      unsolved = solveStages(state, h, tNew, iterations);
    } catch (const StateOutsideDomain& e) {
      outside = e.what();
    }

    if (!outside.empty()) {
      ++stats.rejectedOutsideDomain;
    }
    if (trial && (!unsolved.empty() || !outside.empty())) {
      ++stats.rejectedSteps;
      state.proposedStep = proposedBefore;
      report.stepSize = 0.0;
      return report;
    }
    if (!unsolved.empty() || !outside.empty()) {
      core::require<core::NumericalError>(
          settings_.adaptive, "Time integration failed: ", unsolved.empty() ? outside : unsolved, " in the fixed ",
          R.name, " step from t = ", shown(state.time), " (dt = ", shown(h), "). The state at t = ", shown(state.time),
          " is the last accepted one.");
      ++report.rejectedAttempts;
      ++stats.rejectedSteps;
      // A solve that fails is tried again with a quarter of the step (W closer to I); a
      // state outside the model with half of it, as in the explicit steps.
      state.proposedStep = (unsolved.empty() ? 0.5 : 0.25) * h;
      if (state.proposedStep < settings_.minimumStep) {
        if (!unsolved.empty()) {
          throw core::NumericalError(core::message(
              "Time integration failed at t = ", shown(state.time), ": ", unsolved, ", for every step down to ",
              shown(h), " (below that: 'Time integration/Minimum step' = ", settings_.minimumStep,
              "). The state at t = ", shown(state.time),
              " is the last accepted one. Allow the linear solver more work ", system_->settingsHint(),
              ", or relax 'Time integration/Linear tolerance'."));
        }
        throw core::NumericalError(core::message(
            "Time integration failed: ", outside, " at t = ", shown(state.time), " for every step down to ", shown(h),
            " (below that: 'Time integration/Minimum step' = ", settings_.minimumStep,
            "). The state at t = ", shown(state.time), " is the last accepted one."));
      }
      continue;
    }

    StepDecision decision{true, proposed};
    double errorNorm = 0.0;
    if (settings_.adaptive) {
      combine(std::vector<double>(n, 0.0), difference.data(), increments_, s, errorVector_);
      errorNorm = scaledMaxNorm(errorVector_.data(), state.y.data(), newState_.data(), n, settings_.tolerance,
                                settings_.relativeTolerance);
      decision = rosenbrockController_.decide(h, errorNorm, state.previousErrorNorm, report.rejectedAttempts > 0);
    }
    if (!decision.accepted && trial) {
      ++stats.rejectedSteps;
      state.proposedStep = proposedBefore;
      report.stepSize = 0.0;
      report.errorNorm = errorNorm;
      return report;
    }
    if (!decision.accepted) {
      ++report.rejectedAttempts;
      ++stats.rejectedSteps;
      state.proposedStep = decision.nextStep;
      if (state.proposedStep < settings_.minimumStep) {
        throw core::NumericalError(core::message(
            "Time integration failed: the step size collapsed to ", shown(state.proposedStep),
            " (below Time integration/Minimum step = ", settings_.minimumStep, ") at t = ", shown(state.time),
            " after ", report.rejectedAttempts, " rejected attempts (last error estimate ", errorNorm, ", ", R.name,
            " tolerance ", settings_.tolerance, "). The state at t = ", shown(state.time),
            " is the last accepted one."));
      }
      continue;
    }

    report.stepSize = h;
    report.errorNorm = errorNorm;
    report.linearIterations = iterations;
    if (settings_.steadyCriterion != SteadyStateCriterion::Off) {
      report.steadyMeasure = steadyStateMeasure(settings_.steadyCriterion, state.y.data(), newState_.data(), n, h);
      report.steady = report.steadyMeasure < settings_.steadyTolerance;
    }
    ++stats.acceptedSteps;
    ++stats.stiffSteps;
    stats.stiffRhsEvaluations += stats.rhsEvaluations - rhsBefore;
    if (state.stepsSinceStabilityEstimate < std::numeric_limits<std::int64_t>::max()) {
      ++state.stepsSinceStabilityEstimate; // Auto re-estimates the explicit limit now and then
    }
    stats.smallestStep = std::min(stats.smallestStep, h);
    stats.largestStep = std::max(stats.largestStep, h);
    stats.lastStep = h;
    stats.lastErrorNorm = errorNorm;
    state.y.swap(newState_);
    state.time = tNew;
    state.steady = report.steady;
    if (!report.shortened) {
      state.proposedStep = settings_.adaptive ? std::min(decision.nextStep, settings_.maximumStep) : decision.nextStep;
      if (settings_.adaptive) {
        state.previousErrorNorm = rosenbrockController_.rememberedError(errorNorm);
      }
    } else {
      state.proposedStep = proposed;
    }
    return report;
  }
}

} // namespace capsula::timeint
