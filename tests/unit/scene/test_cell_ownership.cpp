// CellOwnership on one rank: the rank owns every cell, share() leaves the values as they are,
// and forEachOwnedCell stops at the first failing cell and rethrows its error as thrown (the
// 2-rank behaviour is tests/mpi/test_scene_cells_ranks.cpp).
#include <capsula/core/Error.hpp>
#include <capsula/scene/CellOwnership.hpp>

#include <Teuchos_DefaultSerialComm.hpp>

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace {

using capsula::scene::CellOwnership;

TEST(CellOwnership, OneRankOwnsEveryCellAndShareKeepsTheValues)
{
  const CellOwnership ownership(Teuchos::rcp(new Teuchos::SerialComm<int>()), {642, 162, 642});
  EXPECT_EQ(ownership.numCells(), 3);
  EXPECT_EQ(ownership.numOwned(), 3);
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(ownership.owns(c));
    EXPECT_EQ(ownership.owner(c), 0);
  }
  std::vector<double> values = {1.0, -0.0, 2.5, 3.0};
  ownership.share(values, {0, 1, 3, 4});
  EXPECT_EQ(values, (std::vector<double>{1.0, -0.0, 2.5, 3.0}));
  EXPECT_THROW(ownership.share(values, {0, 1, 5}), capsula::core::Error); // offsets for 2 cells, past the end
}

TEST(CellOwnership, TheFirstFailingCellStopsTheLoopWithItsOwnError)
{
  const CellOwnership ownership(Teuchos::rcp(new Teuchos::SerialComm<int>()), {10, 10, 10});
  std::vector<int> visited;
  const auto failAt1 = [&](int c) {
    visited.push_back(c);
    if (c >= 1) {
      throw std::out_of_range("cell " + std::to_string(c));
    }
  };
  try {
    ownership.forEachOwnedCell(failAt1);
    ADD_FAILURE() << "nothing thrown";
  } catch (const std::out_of_range& e) { // not turned into a core::Error on the rank that threw it
    EXPECT_STREQ(e.what(), "cell 1");
  }
  EXPECT_EQ(visited, (std::vector<int>{0, 1}));
  EXPECT_THROW(ownership.onOwner(2, [] { throw capsula::core::NumericalError("folded"); }),
               capsula::core::NumericalError);
}

TEST(CellOwnership, ACellWithoutNodesIsRefused)
{
  EXPECT_THROW(CellOwnership(Teuchos::rcp(new Teuchos::SerialComm<int>()), {10, 0}), capsula::core::InputError);
}

} // namespace
