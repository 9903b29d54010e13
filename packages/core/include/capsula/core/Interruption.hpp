#pragma once
// SIGTERM and SIGINT stop a run cleanly instead of killing it mid-write. The handlers only
// record the signal (nothing else is safe inside a handler); the run asks between steps,
// collectively, so that every rank stops after the same step, writes the checkpoint and
// summary.json there, and throws Interrupted, which core::runApplication turns into one
// line and the exit code 128 + signal (what a shell reports for a process the signal
// killed, so scripts and batch systems read it the same way).
#include <Teuchos_Comm.hpp>

#include <exception>
#include <string>
#include <utility>

namespace capsula::core {

/// Installs the handlers of SIGTERM and SIGINT (once per process; runApplication does).
void installInterruptionHandlers();

/// The signal this process received since the handlers were installed, 0 if none.
int receivedSignal();

/// Collective over `comm`: the signal any rank received (the largest number), 0 if none.
int agreedSignal(const Teuchos::Comm<int>& comm);

/// "SIGTERM", "SIGINT" or "signal N".
std::string signalName(int signal);

/// A run that stopped because of a signal, after it wrote its checkpoint and summary.
/// Not a core::Error: nothing went wrong. what() is the one line to print.
class Interrupted final : public std::exception {
public:
  Interrupted(int signal, std::string message) : signal_(signal), message_(std::move(message)) {}
  int signal() const { return signal_; }
  const char* what() const noexcept override { return message_.c_str(); }

private:
  int signal_;
  std::string message_;
};

} // namespace capsula::core
