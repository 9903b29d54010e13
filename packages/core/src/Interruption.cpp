#include "capsula/core/Interruption.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <csignal>

namespace capsula::core {

namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void recordSignal(int signal)
{
  received = signal;
}

} // namespace

void installInterruptionHandlers()
{
  struct sigaction action {};
  action.sa_handler = recordSignal;
  sigemptyset(&action.sa_mask);
  // Restart interrupted system calls: a write or an MPI wait goes on, the run stops later.
  action.sa_flags = SA_RESTART;
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGINT, &action, nullptr);
}

int receivedSignal()
{
  return static_cast<int>(received);
}

int agreedSignal(const Teuchos::Comm<int>& comm)
{
  const int local = receivedSignal();
  int global = local;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  return global;
}

std::string signalName(int signal)
{
  switch (signal) {
  case SIGTERM:
    return "SIGTERM";
  case SIGINT:
    return "SIGINT";
  default:
    return "signal " + std::to_string(signal);
  }
}

} // namespace capsula::core
