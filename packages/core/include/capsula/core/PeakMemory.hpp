#pragma once
// Peak resident memory, the figure that decides how many cells a rank can hold: the
// kernel's high-water mark of the process (getrusage), which no allocator bookkeeping misses.
#include <Teuchos_Comm.hpp>

#include <vector>

namespace capsula::core {

/// This process's peak resident set size so far, in MiB.
double peakResidentMiB();

/// Every rank's peak resident set size so far, in MiB, in rank order, on every rank.
/// Collective over `comm`.
std::vector<double> peakResidentMiBPerRank(const Teuchos::Comm<int>& comm);

} // namespace capsula::core
