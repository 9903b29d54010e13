#include "capsula/timeint/IntegrationState.hpp"

#include "capsula/core/Error.hpp"

#include <limits>

namespace capsula::timeint {

namespace {

template <typename Map>
const typename Map::mapped_type& entry(const Map& map, const std::string& key, const std::string& source)
{
  const auto it = map.find(key);
  core::require<core::InputError>(it != map.end(), "The time-integration record in '", source, "' has no entry '", key,
                                  "': it was not written by this version of Capsula.");
  return it->second;
}

} // namespace

StateRecord toRecord(const IntegrationState& state)
{
  StateRecord r;
  r.reals["time"] = state.time;
  r.reals["proposed step"] = state.proposedStep;
  r.reals["previous error norm"] = state.previousErrorNorm;
  r.reals["output origin"] = state.outputOrigin;
  r.reals["smallest step"] = state.statistics.smallestStep;
  r.reals["largest step"] = state.statistics.largestStep;
  r.reals["last step"] = state.statistics.lastStep;
  r.reals["last error norm"] = state.statistics.lastErrorNorm;
  r.integers["next output"] = state.nextOutput;
  r.integers["steady"] = state.steady ? 1 : 0;
  r.integers["accepted steps"] = state.statistics.acceptedSteps;
  r.integers["rejected steps"] = state.statistics.rejectedSteps;
  r.integers["rejected outside domain"] = state.statistics.rejectedOutsideDomain;
  r.integers["rhs evaluations"] = state.statistics.rhsEvaluations;
  r.integers["stiff steps"] = state.statistics.stiffSteps;
  r.integers["stiff rhs evaluations"] = state.statistics.stiffRhsEvaluations;
  r.integers["linearisations"] = state.statistics.linearisations;
  r.integers["linear solves"] = state.statistics.linearSolves;
  r.integers["linear iterations"] = state.statistics.linearIterations;
  r.integers["largest linear iterations"] = state.statistics.largestLinearIterations;
  r.integers["failed linear solves"] = state.statistics.failedLinearSolves;
  r.integers["method switches"] = state.statistics.methodSwitches;
  r.integers["stiff active"] = state.stiffActive ? 1 : 0;
  r.integers["stiffness held steps"] = state.stiffnessHeldSteps;
  r.integers["stiff trials failed"] = state.stiffTrialsFailed;
  r.arrays["state"] = state.y;
  if (!state.firstStageDerivative.empty()) {
    r.arrays["first stage derivative"] = state.firstStageDerivative;
  }
  if (!state.stabilityVector.empty()) {
    r.arrays["stability vector"] = state.stabilityVector;
    r.reals["stability step"] = state.stabilityStep;
    r.integers["steps since stability estimate"] = state.stepsSinceStabilityEstimate;
  }
  return r;
}

IntegrationState fromRecord(const StateRecord& record, const std::string& source)
{
  IntegrationState s;
  s.time = entry(record.reals, "time", source);
  s.proposedStep = entry(record.reals, "proposed step", source);
  s.previousErrorNorm = entry(record.reals, "previous error norm", source);
  s.outputOrigin = entry(record.reals, "output origin", source);
  s.statistics.smallestStep = entry(record.reals, "smallest step", source);
  s.statistics.largestStep = entry(record.reals, "largest step", source);
  s.statistics.lastStep = entry(record.reals, "last step", source);
  s.statistics.lastErrorNorm = entry(record.reals, "last error norm", source);
  s.nextOutput = entry(record.integers, "next output", source);
  s.steady = entry(record.integers, "steady", source) != 0;
  s.statistics.acceptedSteps = entry(record.integers, "accepted steps", source);
  s.statistics.rejectedSteps = entry(record.integers, "rejected steps", source);
  s.statistics.rhsEvaluations = entry(record.integers, "rhs evaluations", source);
  // Counters that records of explicit-only or older versions lack read as 0.
  const auto counter = [&record](const char* key) {
    const auto it = record.integers.find(key);
    return it == record.integers.end() ? std::int64_t{0} : it->second;
  };
  s.statistics.stiffSteps = counter("stiff steps");
  s.statistics.stiffRhsEvaluations = counter("stiff rhs evaluations");
  s.statistics.linearisations = counter("linearisations");
  s.statistics.linearSolves = counter("linear solves");
  s.statistics.linearIterations = counter("linear iterations");
  s.statistics.largestLinearIterations = counter("largest linear iterations");
  s.statistics.failedLinearSolves = counter("failed linear solves");
  s.statistics.rejectedOutsideDomain = counter("rejected outside domain");
  s.statistics.methodSwitches = counter("method switches");
  s.stiffActive = counter("stiff active") != 0;
  s.stiffnessHeldSteps = counter("stiffness held steps");
  s.stiffTrialsFailed = counter("stiff trials failed");
  s.y = entry(record.arrays, "state", source);
  const auto fsal = record.arrays.find("first stage derivative");
  if (fsal != record.arrays.end()) {
    s.firstStageDerivative = fsal->second;
    core::require<core::InputError>(s.firstStageDerivative.size() == s.y.size(), "The time-integration record in '",
                                    source, "' is inconsistent: 'first stage derivative' has ",
                                    s.firstStageDerivative.size(), " entries, 'state' has ", s.y.size(), ".");
  }
  const auto stability = record.arrays.find("stability vector");
  if (stability != record.arrays.end()) {
    s.stabilityVector = stability->second;
    s.stabilityStep = entry(record.reals, "stability step", source);
    s.stepsSinceStabilityEstimate = entry(record.integers, "steps since stability estimate", source);
  }
  return s;
}

void stateChangedOutside(IntegrationState& state)
{
  state.firstStageDerivative.clear();
  state.stepsSinceStabilityEstimate = std::numeric_limits<std::int64_t>::max();
}

} // namespace capsula::timeint
