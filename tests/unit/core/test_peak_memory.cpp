// Peak resident memory: positive, one entry per rank, and a high-water mark that a large
// allocation the process touches raises.
#include <capsula/core/PeakMemory.hpp>

#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

#include <vector>

namespace core = capsula::core;

TEST(PeakMemory, IsPositiveAndGrowsWithTouchedMemory)
{
  const double before = core::peakResidentMiB();
  EXPECT_GT(before, 0.0);
  std::vector<char> block(static_cast<std::size_t>(before + 64.0) << 20, 1); // touched: resident
  const double after = core::peakResidentMiB();
  EXPECT_GE(after, before + 64.0) << block[block.size() / 2];
}

TEST(PeakMemory, PerRankHasOneEntryPerRankAndThisRanksValue)
{
  const auto comm = Tpetra::getDefaultComm();
  const std::vector<double> perRank = core::peakResidentMiBPerRank(*comm);
  ASSERT_EQ(perRank.size(), static_cast<std::size_t>(comm->getSize()));
  for (const double mib : perRank) {
    EXPECT_GT(mib, 0.0);
  }
  EXPECT_LE(perRank[comm->getRank()], core::peakResidentMiB());
}
