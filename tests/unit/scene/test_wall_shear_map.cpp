#include <capsula/core/Error.hpp>
#include <capsula/scene/WallShearStressMap.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace {

namespace scene = capsula::scene;

TEST(WallShearStressMap, GridIsCentredOnTheCellAndCoversTheExtents)
{
  const auto grid = scene::WallGrid::around(10.0, -1.0, 3.0, 5.0, 2.0, 0.5);
  EXPECT_EQ(grid.nx, 17);   // 6 spacings upstream, 10 downstream, the centre
  EXPECT_EQ(grid.nz, 9);
  EXPECT_DOUBLE_EQ(grid.node(6, 4)[0], 10.0);
  EXPECT_DOUBLE_EQ(grid.node(6, 4)[2], -1.0);
  EXPECT_DOUBLE_EQ(grid.node(0, 0)[0], 7.0);
  EXPECT_DOUBLE_EQ(grid.node(16, 8)[0], 15.0);
  EXPECT_DOUBLE_EQ(grid.node(16, 8)[1], 0.0);
  EXPECT_EQ(grid.nodes().size(), 17u * 9u);
  // Extents that are not whole spacings are rounded up.
  EXPECT_EQ(scene::WallGrid::around(0.0, 0.0, 0.3, 0.3, 0.3, 0.25).nx, 5);
  EXPECT_THROW(scene::WallGrid::around(0, 0, 1, 1, 1, 0.0), capsula::core::InputError);
}

TEST(WallShearStressMap, AreasAreTrapezoidalAndSplitAtTheCell)
{
  const auto grid = scene::WallGrid::around(0.0, 0.0, 2.0, 4.0, 1.0, 0.5);
  // Everything elevated: the whole rectangle, 2 x 2 upstream and 4 x 2 downstream.
  std::vector<double> stress(static_cast<std::size_t>(grid.numNodes()), 1.2);
  auto areas = scene::elevatedStressAreas(grid, stress, 0.0, 1.05);
  EXPECT_NEAR(areas.upstream, 4.0, 1e-12);
  EXPECT_NEAR(areas.downstream, 8.0, 1e-12);
  // Elevated only where x > 1 (strictly, nodes at 1.5 .. 4): a strip [1.25, 4] x [-1, 1]
  // by the dual cells, 2.75 x 2.
  for (int j = 0; j < grid.nz; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      stress[static_cast<std::size_t>(grid.index(i, j))] = grid.node(i, j)[0] > 1.0 ? 1.06 : 1.0;
    }
  }
  areas = scene::elevatedStressAreas(grid, stress, 0.0, 1.05);
  EXPECT_NEAR(areas.upstream, 0.0, 1e-12);
  EXPECT_NEAR(areas.downstream, 5.5, 1e-12);
  EXPECT_DOUBLE_EQ(areas.minimum, 1.0);
  EXPECT_DOUBLE_EQ(areas.maximum, 1.06);
}

TEST(WallShearStressMap, AreasOutsideTheIsolatedCellsRange)
{
  const auto grid = scene::WallGrid::around(0.0, 0.0, 2.0, 4.0, 1.0, 0.5);   // 6 x 2 in all
  // Below the range where x < -1 (nodes at -2 .. -1.5: dual strip [-2, -1.25] x [-1, 1]),
  // above it where x > 3 (nodes 3.5 .. 4: [3.25, 4] x [-1, 1]), inside elsewhere; the range
  // ends themselves count as inside. Sums of halves and quarters: exact.
  std::vector<double> stress(static_cast<std::size_t>(grid.numNodes()));
  for (int j = 0; j < grid.nz; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const double x = grid.node(i, j)[0];
      stress[static_cast<std::size_t>(grid.index(i, j))] = x < -1.0 ? 0.7 : x > 3.0 ? 1.3 : x == 0.0 ? 0.9 : 1.1;
    }
  }
  auto areas = scene::areasOutsideRange(grid, stress, 0.9, 1.1);
  EXPECT_DOUBLE_EQ(areas.below, 1.5);
  EXPECT_DOUBLE_EQ(areas.above, 1.5);
  areas = scene::areasOutsideRange(grid, stress, 0.0, 10.0);
  EXPECT_DOUBLE_EQ(areas.below + areas.above, 0.0);
  areas = scene::areasOutsideRange(grid, stress, 5.0, 10.0);
  EXPECT_DOUBLE_EQ(areas.below, 12.0);   // the whole grid
}

} // namespace
