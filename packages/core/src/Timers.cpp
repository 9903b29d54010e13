#include "capsula/core/Timers.hpp"

namespace capsula::core {

namespace {

const std::string prefix = "Capsula: ";

// Teuchos keeps every timer made by getNewCounter in one registry, which it exposes to
// its subclasses only.
struct TimerRegistry : Teuchos::PerformanceMonitorBase<Teuchos::Time> {
  using PerformanceMonitorBase::counters;
};

} // namespace

Teuchos::RCP<Teuchos::Time> timer(const std::string& name)
{
  return Teuchos::TimeMonitor::getNewCounter(prefix + name);
}

std::vector<TimerTotal> timerTotals()
{
  std::vector<TimerTotal> totals;
  for (const auto& [name, time] : TimerRegistry::counters()) {
    if (name.compare(0, prefix.size(), prefix) == 0 && time->numCalls() > 0) {
      totals.push_back({name.substr(prefix.size()), time->totalElapsedTime(), time->numCalls()});
    }
  }
  return totals;
}

void printTimerSummary(const Teuchos::Comm<int>& comm, std::ostream& out)
{
  // Union: a timer used on some ranks only still appears.
  Teuchos::TimeMonitor::summarize(Teuchos::rcpFromRef(comm).ptr(), out, false, true, false, Teuchos::Union);
}

} // namespace capsula::core
