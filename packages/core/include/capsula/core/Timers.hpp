#pragma once
// Named timers (Teuchos::TimeMonitor) and the end-of-run summary.
//
//   auto t = capsula::core::timer("Single layer");   // once, e.g. in a constructor
//   { Teuchos::TimeMonitor guard(*t); ... }           // around the work
//
// All Capsula timers are prefixed "Capsula: " so the summary groups them.
#include <Teuchos_Comm.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <iosfwd>
#include <string>

namespace capsula::core {

/// The timer with this name (created on first use).
Teuchos::RCP<Teuchos::Time> timer(const std::string& name);

/// Prints min/mean/max over ranks of every timer; collective over `comm`.
void printTimerSummary(const Teuchos::Comm<int>& comm, std::ostream& out);

} // namespace capsula::core
