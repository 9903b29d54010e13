// One accepted step of a Rosenbrock-W method (RosenbrockTableau.hpp):
//   (I - h gamma J~) u_i = h gamma f(t + alpha_i h, y + sum_{j<i} a_ij u_j) + gamma sum_{j<i} c_ij u_j,
//   y_new = y + sum_i m_i u_i,   e = sum_i (m_i - mEmbedded_i) u_i,
// J~ frozen at (t_n, y_n) by the LinearisedSystem for every attempt of the step.
#include "RosenbrockMethod.hpp"

#include "StepMessages.hpp"

#include "capsula/timeint/TimeIntegrator.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/timeint/VectorNorms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace capsula::timeint::detail {

namespace {

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

// Gustafsson's PI controller for an error estimate of order k: the exponents 0.7/k and
// 0.4/k of Hairer & Wanner (Solving ODEs II, IV.8, eq 8.21 with a PI memory), a growth
// limited to 5x per step as in their stiff codes.
PiControllerParameters controllerFor(const RosenbrockTableau& t)
{
  PiControllerParameters p;
  const double k = t.errorEstimateOrder();
  p.alpha = 0.7 / k;
  p.beta = 0.4 / k;
  p.maximumFactor = 5.0;
  return p;
}

} // namespace

RosenbrockMethod::RosenbrockMethod(RosenbrockTableau tableau, double relativeTolerance, double linearTolerance)
    : tableau_(std::move(tableau)),
      relativeTolerance_(relativeTolerance),
      linearTolerance_(linearTolerance),
      controller_(tableau_.errorEstimateOrder(), controllerFor(tableau_))
{
  for (int i = 0; i < tableau_.stages; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    difference_.push_back(tableau_.m[ii] - tableau_.mEmbedded[ii]);
  }
}

std::string RosenbrockMethod::activeMethodName(const IntegrationState&) const
{
  return tableau_.name;
}

std::string RosenbrockMethod::describe(const TimeIntegrationSettings& s) const
{
  std::ostringstream line;
  line << "time integration: " << s.method << " (Rosenbrock-W, order " << tableau_.order << ", L-stable), tolerance "
       << s.tolerance << "; stage solves to " << linearTolerance_ << " x tolerance";
  return line.str();
}

std::string RosenbrockMethod::solveStages(StepContext& context, IntegrationState& state, double h, double tNew,
                                          int& iterations)
{
  const RosenbrockTableau& R = tableau_;
  LinearisedSystem& system = *context.linearisedSystem();
  const std::size_t n = state.y.size();
  const int s = R.stages;
  IntegrationStatistics& stats = state.statistics;
  const double shift = h * R.gamma;
  const double residualTarget = linearTolerance_ * context.settings().tolerance;
  for (int i = 0; i < s; ++i) {
    const std::vector<double>* slope = &slope_;
    if (i > 0) {
      combine(state.y, &R.a[static_cast<std::size_t>(i * s)], increments_, i, stageState_);
      context.checkDomain(stageState_);
      const double ti = state.time + R.stageTime[static_cast<std::size_t>(i)] * h;
      context.evaluate(ti, stageState_, stageSlope_, state, h, i, R.name);
      slope = &stageSlope_;
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
    const LinearSolveReport solved = system.solve(shift, stageRhs_, u, residualTarget);
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
  requireFiniteNewState(newState_, tNew, R.name, state.time, h);
  context.checkDomain(newState_);
  return "";
}

StepReport RosenbrockMethod::step(StepContext& context, IntegrationState& state, double tStop)
{
  return attempt(context, state, tStop, 0.0);
}

StepReport RosenbrockMethod::attempt(StepContext& context, IntegrationState& state, double tStop, double trialStep)
{
  const TimeIntegrationSettings& settings = context.settings();
  const bool trial = trialStep > 0.0;
  const double proposedBefore = state.proposedStep;
  const RosenbrockTableau& R = tableau_;
  const std::size_t n = state.y.size();
  const int s = R.stages;
  IntegrationStatistics& stats = state.statistics;
  increments_.resize(static_cast<std::size_t>(s));
  stageRhs_.resize(n);
  newState_.resize(n);
  errorVector_.resize(n);

  // f(t_n, y_n) and J~ there serve every attempt of this step.
  const std::int64_t rhsBefore = stats.rhsEvaluations;
  context.evaluate(state.time, state.y, slope_, state, state.proposedStep, 0, R.name);
  context.linearisedSystem()->linearise(state.time, state.y);
  ++stats.linearisations;
  state.firstStageDerivative.clear();

  StepReport report;
  report.stiff = true;
  for (;;) {
    const double proposed = trial               ? trialStep
                            : settings.adaptive ? std::min(state.proposedStep, settings.maximumStep)
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
      unsolved = solveStages(context, state, h, tNew, iterations);
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
          settings.adaptive, "Time integration failed: ", unsolved.empty() ? outside : unsolved, " in the fixed ",
          R.name, " step from t = ", shown(state.time), " (dt = ", shown(h), "). The state at t = ", shown(state.time),
          " is the last accepted one.");
      ++report.rejectedAttempts;
      ++stats.rejectedSteps;
      // A solve that fails is tried again with a quarter of the step (W closer to I); a
      // state outside the model with half of it, as in the explicit steps.
      state.proposedStep = (unsolved.empty() ? 0.5 : 0.25) * h;
      if (state.proposedStep < settings.minimumStep) {
        if (!unsolved.empty()) {
          throw core::NumericalError(core::message(
              "Time integration failed at t = ", shown(state.time), ": ", unsolved, ", for every step down to ",
              shown(h), " (below that: 'Time integration/Minimum step' = ", settings.minimumStep,
              "). The state at t = ", shown(state.time),
              " is the last accepted one. Allow the linear solver more work ",
              context.linearisedSystem()->settingsHint(), ", or relax 'Time integration/Linear tolerance'."));
        }
        throw core::NumericalError(core::message(
            "Time integration failed: ", outside, " at t = ", shown(state.time), " for every step down to ", shown(h),
            " (below that: 'Time integration/Minimum step' = ", settings.minimumStep,
            "). The state at t = ", shown(state.time), " is the last accepted one."));
      }
      continue;
    }

    StepDecision decision{true, proposed};
    double errorNorm = 0.0;
    if (settings.adaptive) {
      combine(std::vector<double>(n, 0.0), difference_.data(), increments_, s, errorVector_);
      errorNorm = scaledMaxNorm(errorVector_.data(), state.y.data(), newState_.data(), n, settings.tolerance,
                                relativeTolerance_);
      decision = controller_.decide(h, errorNorm, state.previousErrorNorm, report.rejectedAttempts > 0);
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
      if (state.proposedStep < settings.minimumStep) {
        throw core::NumericalError(core::message(
            "Time integration failed: the step size collapsed to ", shown(state.proposedStep),
            " (below Time integration/Minimum step = ", settings.minimumStep, ") at t = ", shown(state.time), " after ",
            report.rejectedAttempts, " rejected attempts (last error estimate ", errorNorm, ", ", R.name, " tolerance ",
            settings.tolerance, "). The state at t = ", shown(state.time), " is the last accepted one."));
      }
      continue;
    }

    report.linearIterations = iterations;
    context.recordAcceptedStep(state, report, h, tNew, errorNorm, newState_);
    ++stats.stiffSteps;
    stats.stiffRhsEvaluations += stats.rhsEvaluations - rhsBefore;
    if (state.stepsSinceStabilityEstimate < std::numeric_limits<std::int64_t>::max()) {
      ++state.stepsSinceStabilityEstimate; // Auto re-estimates the explicit limit now and then
    }
    if (context.proposeNextStep(state, report, proposed, decision.nextStep)) {
      state.previousErrorNorm = controller_.rememberedError(errorNorm);
    }
    return report;
  }
}

} // namespace capsula::timeint::detail
