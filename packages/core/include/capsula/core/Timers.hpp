#pragma once
// Named timers (Teuchos::TimeMonitor) and the end-of-run summary.
//
//   auto t = capsula::core::timer("Single layer");   // once, e.g. in a constructor
//   { Teuchos::TimeMonitor guard(*t); ... }           // around the work
//
// All Capsula timers are prefixed "Capsula: " so the summary groups them. A timer is named
// by the component that owns it; a run reports every timer that ran (timerTotals), so a
// new timer needs no list to be kept anywhere else.
#include <Teuchos_Comm.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace capsula::core {

/// The timer with this name (created on first use).
Teuchos::RCP<Teuchos::Time> timer(const std::string& name);

/// A timer's name (without the prefix) and what it measured in this process so far.
struct TimerTotal {
  std::string name;
  double seconds = 0.0;
  int calls = 0;
};

/// Every Capsula timer that has run in this process, by name.
std::vector<TimerTotal> timerTotals();

/// Prints min/mean/max over ranks of every timer; collective over `comm`.
void printTimerSummary(const Teuchos::Comm<int>& comm, std::ostream& out);

} // namespace capsula::core
