#pragma once
// Helpers for tests that run on several ranks: reduce a local verdict over the
// communicator before asserting, so that every rank agrees on pass/fail and no
// rank hangs in a collective after another rank's assertion returned early.
#include <Teuchos_Comm.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>

namespace capsula::testing {

/// True on every rank iff `localOk` is true on every rank.
inline bool allRanks(const Teuchos::Comm<int>& comm, bool localOk)
{
  int local = localOk ? 1 : 0;
  int global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, local, Teuchos::outArg(global));
  return global == 1;
}

/// Maximum of a value over all ranks (e.g. an error norm computed per rank).
inline double maxOverRanks(const Teuchos::Comm<int>& comm, double local)
{
  double global = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  return global;
}

} // namespace capsula::testing
