#pragma once
// Time integration of dy/dt = f(t, y) over a flat state vector (thesis Section 3.10 /
// App. A.8: dx_i/dt = u_i for all node coordinates), explicit or linearly implicit. The
// integrator never knows what the state means.
//
// Methods are plug-ins chosen by name from a MethodRegistry (MethodRegistry.hpp), each a
// class implementing TimeIntegrationMethod (TimeIntegrationMethod.hpp). The built-in ones
// and their error control:
//   RKF45            thesis eqs 3.47-3.50: the 4th-order solution advances (optionally the
//                    5th, "local extrapolation"); err = max_i |x5_i - x4_i|, the largest
//                    difference of any node coordinate (the thesis's |x5 - x4| for the
//                    whole state); ThesisStepController (double/halve; see there for the
//                    acceptance rule). Absolute tolerance eps.
//   DormandPrince45  5th order advances, FSAL; err = scaled RMS norm with
//                    sc_i = Tolerance + Relative tolerance * |y_i|; PiStepController.
//   RK4              classical Runge-Kutta, fixed steps of `initialStep`.
//   ROS34PW2, ROS2   Rosenbrock-W methods for stiff systems (RosenbrockTableau.hpp): each
//                    stage solves with W = I - h gamma J~, J~ ~ df/dy frozen at the step's
//                    start by a LinearisedSystem (setLinearisedSystem); no stability limit on
//                    the step. err = max_i |e_i| / (Tolerance + Relative tolerance |y_i|);
//                    PI controller for the estimate's order. A stage solve that does not
//                    converge rejects the step (a quarter of the step is tried next).
//   Auto             RKF45 with the stability limit, switching to ROS34PW2 when the limit
//                    holds the step and a trial step of ROS34PW2 large enough to pay off
//                    meets the tolerance, and back when RKF45 would advance further per
//                    unit of work (see AutoSwitchingMethod.cpp). Needs a LinearisedSystem too.
// Any method runs with fixed steps when `adaptive` is false (tests, benchmarks).
//
// Stability limit (optional, adaptive runs): an elastic membrane makes the system stiff,
// its fastest mode decaying at a rate rho ~ G / (mu h) that grows as the elements shrink.
// The error estimate of an explicit pair sees such a mode only once it has started to
// grow, and at loose tolerances (1e-4 on a level-2 capsule) accepts steps beyond h rho = r,
// the method's real stability boundary, and the membrane folds within a few steps. With
// the limit on, rho is estimated every `stabilityInterval` accepted steps by power
// iteration on finite differences of f (12 evaluations the first time, 3 warm-started
// after) and every step is capped at 0.8 r / rho.
//
// Failures: a non-finite right-hand side or state, and a step size driven below
// `minimumStep`, throw core::NumericalError naming the time and the step size. The state
// (time, y) is then the last accepted one, untouched, so the caller can checkpoint it.
#include "capsula/core/Error.hpp"
#include "capsula/timeint/IntegrationState.hpp"
#include "capsula/timeint/LinearisedSystem.hpp"
#include "capsula/timeint/MethodRegistry.hpp"
#include "capsula/timeint/SteadyState.hpp"
#include "capsula/timeint/TimeIntegrationMethod.hpp"

#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace capsula::timeint {

/// Thrown by a domain check (TimeIntegrator::setDomainCheck) for a state the model is not
/// defined at, e.g. a node on or below the wall, where the wall kernel meets its own image.
/// Inside an adaptive step it is not a failure: an explicit step evaluates stage states the
/// error control has not judged yet, and a step too large for a fast mode can put one
/// outside although smaller steps stay inside. The attempt is rejected and retried with
/// half the step; the run fails (core::NumericalError) only when the step falls below the
/// minimum, or at once with fixed steps.
class StateOutsideDomain : public core::Error {
public:
  explicit StateOutsideDomain(const std::string& message) : core::Error(message) {}
};

enum class OutputReason { Start, Interval, End, SteadyState };

/// Called by integrate() at output times with the accepted state there.
using Observer = std::function<void(const IntegrationState& state, OutputReason reason)>;

/// Output k (k = 1, 2, ...) is due at state.outputOrigin + k * interval, and the last at
/// the end time; interval 0 means the end time only. Start: output 0, at the first call
/// on a fresh state. A run whose outputs fall elsewhere (a stage timed from its own origin
/// in a scaled time) gives their times instead: `times(k)` for k >= 1, increasing, the
/// last one at `endTime`, where the integration then ends instead of at the settings' end
/// time.
struct OutputSchedule {
  OutputSchedule() = default;
  OutputSchedule(double outputInterval, bool observeTheStart = true)
      : interval(outputInterval), observeStart(observeTheStart)
  {}

  double interval = 0.0;
  bool observeStart = true;
  std::function<double(std::int64_t index)> times; ///< empty: origin + k * interval
  std::optional<double> endTime;                   ///< empty: TimeIntegrationSettings::endTime
};

/// Requested: an IntegrationObserver ended the integration (after a step or an output).
enum class StopReason { EndTime, SteadyState, Requested };

/// What an IntegrationObserver tells integrate(): go on, or end the integration here.
enum class ObserverVerdict { Continue, Stop };

/// A part of a run that integrate() keeps informed: the outputs, and whatever a run does
/// between them (a mesh regularisation after a step, a stop when two cells meet, progress
/// lines, the events of a tether procedure). Every member has a default that does nothing.
class IntegrationObserver {
public:
  virtual ~IntegrationObserver() = default;
  /// A time after state.time that the next step must land on besides the output times (an
  /// event of the run, e.g. a check of a criterion), or +infinity for none.
  virtual double nextEvent(const IntegrationState& state);
  /// After every accepted step, before the output due at its time (`atOutputTime`). May
  /// change the state (call stateChangedOutside after changing y). Stop ends the
  /// integration at once: the observers after this one are not called, and no output
  /// follows.
  virtual ObserverVerdict afterStep(IntegrationState& state, const StepReport& report, bool atOutputTime);
  /// At output times. Every observer sees the output; if one says Stop, the integration
  /// ends after it.
  virtual ObserverVerdict atOutput(const IntegrationState& state, OutputReason reason);
};

class TimeIntegrator {
public:
  /// The method settings.method names, from `methods`. Throws core::InputError naming the
  /// deck key ("Time integration/Minimum step", "Time integration/Method", ...) if the
  /// settings are inconsistent or the method is not registered.
  TimeIntegrator(TimeIntegrationSettings settings, RightHandSide rhs, const MethodRegistry& methods = builtInMethods());

  void setStageConstraint(StageConstraint constraint);
  /// J~ and the solves of the stiff methods (required by those whose MethodTraits say so:
  /// ROS34PW2, ROS2 and Auto; the integrator shares ownership). It must include the stage
  /// constraint (LinearisedSystem.hpp).
  void setLinearisedSystem(std::shared_ptr<LinearisedSystem> system);
  bool hasLinearisedSystem() const { return context_.linearisedSystem() != nullptr; }
  /// Whether the method needs setLinearisedSystem before the first step.
  bool needsLinearisedSystem() const { return traits_.linearisedSystem; }
  /// Every stage state and every step's result is checked before use (see
  /// StateOutsideDomain); the start state is expected inside.
  void setDomainCheck(DomainCheck check);

  /// The settings as checked (a fixed-step method runs with adaptive false, a method that
  /// judges stiffness by the stability limit with the limit on).
  const TimeIntegrationSettings& settings() const { return context_.settings(); }
  bool adaptive() const;
  /// The method the next step of `state` will use: the deck's, or for Auto the active one.
  std::string activeMethodName(const IntegrationState& state) const;
  /// One line for a run's "Terms built": the method, its tolerance and what limits its steps.
  std::string describe() const;

  /// A fresh state at (t0, y0) with the initial step proposed.
  IntegrationState start(double t0, std::vector<double> y0) const;

  /// Advances `state` by one accepted step of the method that ends at or before tStop
  /// (> state.time) (TimeIntegrationMethod::step). Rejected attempts are retried with
  /// smaller steps. A step that would pass tStop is shortened to end exactly on it, and one
  /// that would stop short of it by less than 1% of its size is stretched onto it (no
  /// sliver steps). The step size proposed before such an adjustment is kept for the next
  /// step (an adjusted step changes the proposal only through a rejection).
  StepReport step(IntegrationState& state, double tStop);

  /// The time loop of every run: steps from state.time to the end time (settings() or
  /// the schedule's), landing exactly on every output time and every observer's next
  /// event, and calling the observers after each step and at each output (never inside a
  /// step). Stops early, after one more observation, when steady state is detected, and
  /// when an observer says so. Continuing from a copy of the state that an observer
  /// received at an output reproduces the uninterrupted run bit for bit.
  StopReason integrate(IntegrationState& state, const OutputSchedule& schedule,
                       std::initializer_list<IntegrationObserver*> observers);
  /// The same with observers that only watch the outputs.
  StopReason integrate(IntegrationState& state, const OutputSchedule& schedule, const std::vector<Observer>& observers);

  /// The time of output `index` under `schedule` for a run started at `origin`.
  double outputTime(double origin, std::int64_t index, const OutputSchedule& schedule) const;
  /// Where integrate() ends under `schedule`.
  double endTime(const OutputSchedule& schedule) const;

private:
  StopReason integrateWith(IntegrationState& state, const OutputSchedule& schedule,
                           const std::vector<IntegrationObserver*>& observers);

  MethodTraits traits_;
  StepContext context_;
  std::unique_ptr<TimeIntegrationMethod> method_;
};

} // namespace capsula::timeint
