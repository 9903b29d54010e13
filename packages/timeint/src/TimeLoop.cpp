// The time loop of TimeIntegrator (integrate) and its output schedule: where the steps
// must land and whom they tell. The step itself is TimeIntegrator.cpp.
#include "capsula/timeint/TimeIntegrator.hpp"

#include <limits>

namespace capsula::timeint {

double IntegrationObserver::nextEvent(const IntegrationState&)
{
  return std::numeric_limits<double>::infinity();
}

ObserverVerdict IntegrationObserver::afterStep(IntegrationState&, const StepReport&, bool)
{
  return ObserverVerdict::Continue;
}

ObserverVerdict IntegrationObserver::atOutput(const IntegrationState&, OutputReason)
{
  return ObserverVerdict::Continue;
}

double TimeIntegrator::endTime(const OutputSchedule& schedule) const
{
  return schedule.endTime ? *schedule.endTime : settings().endTime;
}

double TimeIntegrator::outputTime(double origin, std::int64_t index, const OutputSchedule& schedule) const
{
  if (schedule.times) {
    return index == 0 ? origin : schedule.times(index);
  }
  const double end = endTime(schedule);
  if (!(schedule.interval > 0.0)) {
    return index == 0 ? origin : end;
  }
  const double t = origin + static_cast<double>(index) * schedule.interval;
  // An output within a hair of the end time is the end time (no sliver step before it).
  return t >= end - 1.0e-9 * schedule.interval ? end : t;
}

namespace {

/// Observers that only watch the outputs (the function form of integrate()).
class OutputWatcher final : public IntegrationObserver {
public:
  explicit OutputWatcher(const Observer& observe) : observe_(observe) {}
  ObserverVerdict atOutput(const IntegrationState& state, OutputReason reason) override
  {
    observe_(state, reason);
    return ObserverVerdict::Continue;
  }

private:
  const Observer& observe_;
};

} // namespace

StopReason TimeIntegrator::integrate(IntegrationState& state, const OutputSchedule& schedule,
                                     const std::vector<Observer>& observers)
{
  std::vector<OutputWatcher> watchers;
  watchers.reserve(observers.size());
  std::vector<IntegrationObserver*> pointers;
  for (const auto& observe : observers) {
    pointers.push_back(&watchers.emplace_back(observe));
  }
  return integrateWith(state, schedule, pointers);
}

StopReason TimeIntegrator::integrate(IntegrationState& state, const OutputSchedule& schedule,
                                     std::initializer_list<IntegrationObserver*> observers)
{
  return integrateWith(state, schedule, std::vector<IntegrationObserver*>(observers));
}

StopReason TimeIntegrator::integrateWith(IntegrationState& state, const OutputSchedule& schedule,
                                         const std::vector<IntegrationObserver*>& observers)
{
  const auto notify = [&](OutputReason reason) {
    bool stop = false;
    for (auto* observer : observers) {
      stop = observer->atOutput(state, reason) == ObserverVerdict::Stop || stop;
    }
    return stop;
  };
  if (state.nextOutput == 0) {
    state.nextOutput = 1; // counted before the observers see (and may checkpoint) the state
    if (schedule.observeStart && notify(OutputReason::Start)) {
      return StopReason::Requested;
    }
  }
  if (state.steady) {
    return StopReason::SteadyState;
  }
  const double end = endTime(schedule);
  while (state.time < end) {
    // Outputs at or before the current time are past (a restart with another interval).
    while (outputTime(state.outputOrigin, state.nextOutput, schedule) <= state.time) {
      ++state.nextOutput;
    }
    const double tOut = outputTime(state.outputOrigin, state.nextOutput, schedule);
    while (state.time < tOut && !state.steady) {
      double tStop = tOut;
      for (auto* observer : observers) {
        const double event = observer->nextEvent(state);
        if (event > state.time && event < tStop) {
          tStop = event;
        }
      }
      const StepReport report = step(state, tStop);
      for (auto* observer : observers) {
        if (observer->afterStep(state, report, state.time == tOut) == ObserverVerdict::Stop) {
          return StopReason::Requested;
        }
      }
    }
    if (state.time == tOut) {
      ++state.nextOutput;
    }
    if (state.steady) {
      notify(OutputReason::SteadyState);
      return StopReason::SteadyState;
    }
    if (notify(state.time == end ? OutputReason::End : OutputReason::Interval)) {
      return StopReason::Requested;
    }
  }
  return StopReason::EndTime;
}

} // namespace capsula::timeint
