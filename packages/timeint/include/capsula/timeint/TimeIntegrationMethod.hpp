#pragma once
// A time-integration method as a plug-in: what TimeIntegrator asks of a method (one
// accepted step, its name, one line describing it) and what a method may use of the
// integrator (StepContext: the right-hand side with its stage constraint and checks, the
// domain check, the linearised system, the stability limit and the bookkeeping of an
// accepted step). Methods are created by name from a MethodRegistry (MethodRegistry.hpp);
// the integrator's loop, output times, observers and restart never depend on which one.
#include "capsula/timeint/IntegrationState.hpp"
#include "capsula/timeint/LinearisedSystem.hpp"
#include "capsula/timeint/SteadyState.hpp"
#include "capsula/timeint/StepControllers.hpp"

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace capsula::timeint {

/// Checks a state; throws StateOutsideDomain (TimeIntegrator.hpp) if the model is not
/// defined there.
using DomainCheck = std::function<void(const std::vector<double>& y)>;

/// dy/dt = f(t, y). `dydt` arrives sized like `y`; the function fills every entry and
/// must be a pure function of (t, y) (a restarted run relies on it).
using RightHandSide = std::function<void(double t, const std::vector<double>& y, std::vector<double>& dydt)>;

/// Called right after every right-hand-side evaluation with the stage's (t, y); may
/// modify the stage derivative in place (a tethered node's velocity set to zero, the mean
/// vertical velocity of a fixed-height cell subtracted, ...).
using StageConstraint = std::function<void(double t, const std::vector<double>& y, std::vector<double>& dydt)>;

struct TimeIntegrationSettings {
  /// The method's name in the MethodRegistry (the deck's 'Time integration/Method').
  std::string method = "RKF45";
  bool adaptive = true;         ///< false: fixed steps of initialStep (always for a fixed-step method)
  double tolerance = 1.0e-6;    ///< the local error tolerance; each method says how it measures the error
  double initialStep = 1.0e-3;  ///< first attempted step; the step of fixed-step runs
  double minimumStep = 1.0e-12; ///< a controller step below this is a failure
  double maximumStep = 1.0;     ///< the controller never proposes more
  /// Adaptive explicit steps: cap the step at 0.8 r / rho, rho the spectral radius of
  /// df/dy estimated by power iteration, r the method's real stability boundary.
  /// Off: the error control alone chooses the step.
  bool stabilityLimit = false;
  int stabilityInterval = 10; ///< accepted steps between estimates of rho
  double endTime = 1.0;       ///< where integrate() stops
  SteadyStateCriterion steadyCriterion = SteadyStateCriterion::Off;
  double steadyTolerance = 0.0; ///< steady when the measure falls below this
  PiControllerParameters piController;
  /// The keys the methods own ('Local extrapolation', 'Linear tolerance', ...; MethodInfo::
  /// keys): one of the chosen method not given here takes its declared default, and one
  /// that only other methods own must keep its default.
  Teuchos::ParameterList methodParameters;
};

/// What one accepted step did.
struct StepReport {
  double stepSize = 0.0;
  double errorNorm = 0.0; ///< 0 for fixed steps
  int rejectedAttempts = 0;
  bool shortened = false;     ///< cut short to land on the stop time
  double steadyMeasure = 0.0; ///< 0 when steady-state detection is off
  bool steady = false;
  bool stiff = false;       ///< taken by a linearly implicit method
  int linearIterations = 0; ///< Krylov iterations of the accepted attempt's solves
  /// An explicit step under the stability limit that the limit bound.
  bool heldByStabilityLimit = false;
  /// A switching method: why the method changed after this step ("" if it did not).
  std::string switchReason;
};

/// What a method uses of the integrator during a step. One per TimeIntegrator.
class StepContext {
public:
  StepContext(TimeIntegrationSettings settings, RightHandSide rhs);

  /// The integrator's settings (checked; methodParameters are the method's own business).
  const TimeIntegrationSettings& settings() const { return settings_; }

  void setStageConstraint(StageConstraint constraint) { constraint_ = std::move(constraint); }
  void setDomainCheck(DomainCheck check) { domainCheck_ = std::move(check); }
  void setLinearisedSystem(std::shared_ptr<LinearisedSystem> system) { system_ = std::move(system); }
  /// Null unless the model provides one (TimeIntegrator::setLinearisedSystem).
  LinearisedSystem* linearisedSystem() const { return system_.get(); }

  /// dydt = f(t, y) followed by the stage constraint; counts the evaluation and throws
  /// core::NumericalError naming the time, `stage` (0-based) of `method`'s step of size
  /// `step` from state.time, if dydt is not finite.
  void evaluate(double t, const std::vector<double>& y, std::vector<double>& dydt, IntegrationState& state, double step,
                int stage, const std::string& method);
  /// Throws StateOutsideDomain if the model's domain check refuses y (no-op without one).
  void checkDomain(const std::vector<double>& y) const;

  /// The stability limit: rho, the spectral radius of df/dy at (state.time, state.y), by
  /// power iteration on finite differences of f (`slope` = f there), warm-started from
  /// state.stabilityVector; sets state.stabilityStep = 0.8 r / rho for the real stability
  /// boundary r of the explicit method `method`, and restarts the count of steps since.
  void estimateStabilityStep(IntegrationState& state, const std::vector<double>& slope, double boundary,
                             const std::string& method);

  /// The bookkeeping of every accepted step of size h from state.time to tNew with the
  /// error norm `errorNorm`: fills the report's step size, error norm and steady-state
  /// measure, counts the step, and moves newState into state.y (newState gets the old y).
  void recordAcceptedStep(IntegrationState& state, StepReport& report, double h, double tNew, double errorNorm,
                          std::vector<double>& newState) const;
  /// The proposal after an accepted step: the controller's `nextStep` (capped at the
  /// maximum step when adaptive), or, for a step adjusted to land on the stop time (which
  /// says little about the step wanted elsewhere), the `proposed` step it was cut from.
  /// Returns whether the controller's memory should be updated (an adaptive step not
  /// adjusted).
  bool proposeNextStep(IntegrationState& state, const StepReport& report, double proposed, double nextStep) const;

private:
  TimeIntegrationSettings settings_;
  RightHandSide rhs_;
  StageConstraint constraint_;
  DomainCheck domainCheck_;
  std::shared_ptr<LinearisedSystem> system_;
  std::vector<double> probe_, probeSlope_; // the stability limit's y + eps v and f there
};

/// One time-integration method. A method keeps the settings of its own keys (given to its
/// factory) and its work arrays; everything carried from one step to the next is in the
/// IntegrationState, so that a restart continues bit for bit.
class TimeIntegrationMethod {
public:
  virtual ~TimeIntegrationMethod() = default;

  /// Advances `state` by one accepted step that ends at or before tStop (> state.time),
  /// retrying rejected attempts with smaller steps. A step that would pass tStop is
  /// shortened to end exactly on it, and one that would stop short of it by less than 1%
  /// of its size (detail::stretchFraction) is stretched onto it. On failure it throws
  /// core::NumericalError with the state the last accepted one.
  virtual StepReport step(StepContext& context, IntegrationState& state, double tStop) = 0;

  /// The scheme that takes the next step of `state` (a switching method: the active one).
  virtual std::string activeMethodName(const IntegrationState& state) const = 0;

  /// One line for a run's "Terms built": "time integration: <name>, ..." with what limits
  /// its steps.
  virtual std::string describe(const TimeIntegrationSettings& settings) const = 0;
};

} // namespace capsula::timeint
