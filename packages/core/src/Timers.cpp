#include "capsula/core/Timers.hpp"

namespace capsula::core {

Teuchos::RCP<Teuchos::Time> timer(const std::string& name)
{
  return Teuchos::TimeMonitor::getNewCounter("Capsula: " + name);
}

void printTimerSummary(const Teuchos::Comm<int>& comm, std::ostream& out)
{
  // Union: a timer used on some ranks only still appears.
  Teuchos::TimeMonitor::summarize(Teuchos::rcpFromRef(comm).ptr(), out, false, true, false,
                                  Teuchos::Union);
}

} // namespace capsula::core
