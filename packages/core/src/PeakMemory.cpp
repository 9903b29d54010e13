#include "capsula/core/PeakMemory.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <sys/resource.h>

namespace capsula::core {

double peakResidentMiB()
{
  struct rusage usage {};
  if (getrusage(RUSAGE_SELF, &usage) != 0) {
    return 0.0;
  }
  // Linux gives ru_maxrss in KiB.
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

std::vector<double> peakResidentMiBPerRank(const Teuchos::Comm<int>& comm)
{
  const double local = peakResidentMiB();
  std::vector<double> all(static_cast<std::size_t>(comm.getSize()));
  Teuchos::gatherAll(comm, 1, &local, comm.getSize(), all.data());
  return all;
}

} // namespace capsula::core
