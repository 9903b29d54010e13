// The main() of every Capsula test executable.
//
// MPI and Kokkos are initialised once through Tpetra::ScopeGuard, so the same
// binary runs alone or under mpiexec. Only rank 0 keeps GoogleTest's printer;
// other ranks report failures through the exit code (MPI tests reduce their
// pass/fail across ranks before asserting, see MpiTesting.hpp). ctest runs the tests side
// by side, so each singleton gets its own Open MPI session directory (MpiSessionDirectory.hpp).
#include <capsula/core/MpiSessionDirectory.hpp>

#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

int main(int argc, char** argv)
{
  const capsula::core::MpiSessionDirectory sessionDirectory; // outlives MPI
  Tpetra::ScopeGuard tpetraScope(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  const auto comm = Tpetra::getDefaultComm();
  if (comm->getRank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int localResult = RUN_ALL_TESTS();
  int globalResult = localResult;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, localResult, Teuchos::outArg(globalResult));
  return globalResult;
}
