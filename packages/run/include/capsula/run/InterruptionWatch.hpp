#pragma once
// The time loop's part in a clean stop on SIGTERM or SIGINT (core/Interruption.hpp): after
// every step, all ranks agree whether one of them received a signal, and if so every rank
// stops after that same step. A step that lands on an output time stops after its output
// instead (a restart would skip an output left out there). The run then writes its
// checkpoint and summary.json at the step reached and throws core::Interrupted.
//
// Observed last: the other observers see the step (a mesh regularisation, a gap check)
// before the loop ends, so the checkpoint holds the state the uninterrupted run goes on from.
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_Comm.hpp>

namespace capsula::run {

class InterruptionWatch final : public timeint::IntegrationObserver {
public:
  explicit InterruptionWatch(const Teuchos::Comm<int>& comm) : comm_(comm) {}

  timeint::ObserverVerdict afterStep(timeint::IntegrationState& state, const timeint::StepReport& report,
                                     bool atOutputTime) override;
  /// At the end time or steady state the run is over: a signal there is not acted on.
  timeint::ObserverVerdict atOutput(const timeint::IntegrationState& state, timeint::OutputReason reason) override;

  /// The signal the ranks agreed on, 0 while none.
  int signal() const { return signal_; }

private:
  timeint::ObserverVerdict check();

  const Teuchos::Comm<int>& comm_;
  int signal_ = 0;
};

} // namespace capsula::run
