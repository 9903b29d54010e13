// A signal that reaches one rank stops every rank: agreedSignal reduces the flag the
// handlers set over the communicator. Its own executable: it installs signal handlers.
#include "capsula/testing/MpiTesting.hpp"

#include <capsula/core/Interruption.hpp>

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

#include <csignal>

TEST(MpiInterruption, ASignalOnOneRankIsAgreedByAll)
{
  const auto comm = Tpetra::getDefaultComm();
  capsula::core::installInterruptionHandlers();
  EXPECT_EQ(capsula::core::agreedSignal(*comm), 0);
  if (comm->getRank() == comm->getSize() - 1) {
    std::raise(SIGINT); // the handler records it; the process goes on
  }
  const int expected = comm->getRank() == comm->getSize() - 1 ? SIGINT : 0;
  EXPECT_TRUE(capsula::testing::allRanks(*comm, capsula::core::receivedSignal() == expected));
  EXPECT_EQ(capsula::core::agreedSignal(*comm), SIGINT);
  EXPECT_EQ(capsula::core::signalName(SIGINT), "SIGINT");
  EXPECT_EQ(capsula::core::signalName(SIGTERM), "SIGTERM");
}
