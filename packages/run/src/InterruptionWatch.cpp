#include "capsula/run/InterruptionWatch.hpp"

#include <capsula/core/Interruption.hpp>

namespace capsula::run {

timeint::ObserverVerdict InterruptionWatch::check()
{
  signal_ = core::agreedSignal(comm_);
  return signal_ != 0 ? timeint::ObserverVerdict::Stop : timeint::ObserverVerdict::Continue;
}

timeint::ObserverVerdict InterruptionWatch::afterStep(timeint::IntegrationState&, const timeint::StepReport&,
                                                      bool atOutputTime)
{
  // Every rank holds the same state, so every rank takes this branch alike.
  return atOutputTime ? timeint::ObserverVerdict::Continue : check();
}

timeint::ObserverVerdict InterruptionWatch::atOutput(const timeint::IntegrationState&, timeint::OutputReason reason)
{
  if (reason == timeint::OutputReason::End || reason == timeint::OutputReason::SteadyState) {
    return timeint::ObserverVerdict::Continue;
  }
  return check();
}

} // namespace capsula::run
