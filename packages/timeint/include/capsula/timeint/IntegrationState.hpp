#pragma once
// Everything a time integration carries from one step to the next. Copying this struct
// (or writing it to a checkpoint and reading it back, see toRecord/fromRecord) and
// continuing from the copy reproduces the uninterrupted run bit for bit.
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace capsula::timeint {

struct IntegrationStatistics {
  std::int64_t acceptedSteps = 0;
  std::int64_t rejectedSteps = 0;         ///< attempts rejected, for any reason
  std::int64_t rejectedOutsideDomain = 0; ///< of those, with a stage state or result outside the model
  std::int64_t rhsEvaluations = 0;        ///< calls of the right-hand side
  double smallestStep = std::numeric_limits<double>::infinity(); ///< over accepted steps
  double largestStep = 0.0;                                      ///< over accepted steps
  double lastStep = 0.0;                                         ///< size of the last accepted step
  double lastErrorNorm = 0.0;                                    ///< error estimate of the last accepted step
  // Linearly implicit (stiff) steps; all zero for an explicit method.
  std::int64_t stiffSteps = 0;              ///< accepted steps taken by the stiff method
  std::int64_t stiffRhsEvaluations = 0;     ///< right-hand sides evaluated in stiff steps
  std::int64_t linearisations = 0;          ///< J~ frozen (LinearisedSystem::linearise)
  std::int64_t linearSolves = 0;            ///< solves with W = I - h gamma J~
  std::int64_t linearIterations = 0;        ///< their Krylov iterations, summed
  std::int64_t largestLinearIterations = 0; ///< the most iterations one solve took
  std::int64_t failedLinearSolves = 0;      ///< solves that did not converge (step rejected)
  std::int64_t methodSwitches = 0;          ///< Method Auto: changes between explicit and stiff
};

struct IntegrationState {
  double time = 0.0;
  std::vector<double> y;     ///< the state the right-hand side advances
  double proposedStep = 0.0; ///< size of the next attempt
  /// PI controller memory: the previous accepted error norm (unused by other controllers).
  double previousErrorNorm = 0.0;
  /// f(time, y) when the method is "first same as last" and it is known; empty otherwise.
  /// Keeping it saves one right-hand-side evaluation per step and on restart.
  std::vector<double> firstStageDerivative;
  /// Output bookkeeping of TimeIntegrator::integrate: output k is due at
  /// outputOrigin + k * interval; nextOutput is the next k to observe.
  double outputOrigin = 0.0;
  std::int64_t nextOutput = 0;
  bool steady = false; ///< steady state was detected
  /// Stability limit (TimeIntegrationSettings::stabilityLimit): the power iteration's
  /// last vector (the direction of the dominant mode of df/dy; empty before the first
  /// estimate), the step it allows, and the accepted steps since it was estimated.
  std::vector<double> stabilityVector;
  double stabilityStep = std::numeric_limits<double>::infinity();
  std::int64_t stepsSinceStabilityEstimate = 0;
  /// Method Auto: the stiff method is the one in use; how many consecutive explicit steps
  /// the stability limit has held; how often a trial of the stiff method failed or it
  /// handed back (each doubles the held steps before the next trial).
  bool stiffActive = false;
  std::int64_t stiffnessHeldSteps = 0;
  std::int64_t stiffTrialsFailed = 0;
  IntegrationStatistics statistics;
};

/// After the caller changed `state.y` between steps (a mesh regularisation moved nodes):
/// forgets what the integrator derived from the old y (the first-stage slope) and has the
/// stability limit estimated again before the next step.
void stateChangedOutside(IntegrationState& state);

/// Named numbers and arrays, the form in which a state goes into a checkpoint file.
struct StateRecord {
  std::map<std::string, double> reals;
  std::map<std::string, std::int64_t> integers;
  std::map<std::string, std::vector<double>> arrays;
};

/// All fields under fixed names: reals "time", "proposed step", ...; integers
/// "accepted steps", ...; arrays "state" and, if known, "first stage derivative".
/// Records written before the stiff-method counters existed read back with those at 0.
StateRecord toRecord(const IntegrationState& state);

/// The inverse of toRecord. Throws core::InputError naming `source` and the missing
/// entry if the record lacks one.
IntegrationState fromRecord(const StateRecord& record, const std::string& source);

} // namespace capsula::timeint
