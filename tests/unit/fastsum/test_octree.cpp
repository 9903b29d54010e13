// The octree of the treecode: every point in exactly one leaf, ranges nested, tight boxes,
// leaf sizes, and the near-cubic splitting of flat clusters.
#include <capsula/fastsum/Octree.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using capsula::fastsum::Cluster;
using capsula::fastsum::Octree;

namespace {

std::vector<double> uniformValues(int n, double lo, double hi, std::mt19937& random)
{
  std::uniform_real_distribution<double> d(lo, hi);
  std::vector<double> v(n);
  for (auto& value : v) {
    value = d(random);
  }
  return v;
}

} // namespace

TEST(Octree, LeavesPartitionThePointsAndBoxesAreTight)
{
  std::mt19937 random(7);
  const int n = 5000;
  const auto x = uniformValues(n, 0.0, 1.0, random);
  const auto y = uniformValues(n, -2.0, 0.5, random);
  const auto z = uniformValues(n, 3.0, 3.2, random);
  const Octree tree(x.data(), y.data(), z.data(), n, 50);
  // The tree order is a permutation carrying the coordinates with it.
  std::vector<int> sorted = tree.order();
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < n; ++k) {
    ASSERT_EQ(sorted[k], k);
    ASSERT_EQ(tree.x()[k], x[tree.order()[k]]);
    ASSERT_EQ(tree.z()[k], z[tree.order()[k]]);
  }
  std::vector<int> covered(n, 0);
  for (const Cluster& c : tree.clusters()) {
    // Tight box: every point inside, and each face touched by a point.
    const std::vector<double>* coordinates[3] = {&tree.x(), &tree.y(), &tree.z()};
    for (int axis = 0; axis < 3; ++axis) {
      const auto [lo, hi] =
          std::minmax_element(coordinates[axis]->begin() + c.begin, coordinates[axis]->begin() + c.end);
      EXPECT_EQ(*lo, c.box.lo[axis]);
      EXPECT_EQ(*hi, c.box.hi[axis]);
    }
    if (c.isLeaf()) {
      EXPECT_LE(c.size(), 50);
      for (int k = c.begin; k < c.end; ++k) {
        ++covered[k];
      }
    } else {
      // Children tile the parent's range in order.
      int next = c.begin;
      for (int k = 0; k < c.numChildren; ++k) {
        const Cluster& child = tree.clusters()[c.firstChild + k];
        EXPECT_EQ(child.begin, next);
        EXPECT_EQ(child.level, c.level + 1);
        next = child.end;
      }
      EXPECT_EQ(next, c.end);
      EXPECT_GE(c.numChildren, 2);
    }
  }
  EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int k) { return k == 1; }));
}

TEST(Octree, ClusterIsHalvedAlongItsLongestSide)
{
  // Points in a 1 x 0.01 x 0.5 slab: the root is cut in x only (2 children).
  std::mt19937 random(3);
  const int n = 400;
  const auto x = uniformValues(n, 0.0, 1.0, random);
  const auto y = uniformValues(n, 0.0, 0.01, random);
  const auto z = uniformValues(n, 0.0, 0.5, random);
  const Octree tree(x.data(), y.data(), z.data(), n, 10);
  ASSERT_EQ(tree.clusters()[0].numChildren, 2);
  const Cluster& first = tree.clusters()[tree.clusters()[0].firstChild];
  EXPECT_LE(first.box.hi[0], 0.5 * (tree.clusters()[0].box.lo[0] + tree.clusters()[0].box.hi[0]));
}

TEST(Octree, CoincidingPointsStayInOneLeaf)
{
  const std::vector<double> x(30, 1.0), y(30, 2.0), z(30, 3.0);
  const Octree tree(x.data(), y.data(), z.data(), 30, 4);
  ASSERT_EQ(tree.clusters().size(), 1u);
  EXPECT_EQ(tree.clusters()[0].size(), 30);
  EXPECT_EQ(tree.clusters()[0].box.radius(), 0.0);
}

TEST(Octree, EmptySetHasNoClusters)
{
  const Octree tree(nullptr, nullptr, nullptr, 0, 4);
  EXPECT_TRUE(tree.clusters().empty());
  EXPECT_EQ(tree.numPoints(), 0);
}
