#pragma once
// An adaptive octree on a point set (the sources of the treecode, or its targets grouped
// into batches), Wang, Tlupova & Krasny (2020), Section 3.1.
//
// A cluster is split in two at the midpoint of the longest side of its tight bounding box
// (all longest sides if several are equal), so a flat cluster (a patch of membrane) never
// gets thin children and the aspect ratio stays below about 2. Halving rather than the
// paper's octants (Section 3.1) makes the cluster sizes a finer ladder: a cluster that fails
// the acceptance test is replaced by two of half its size, which are more often still large
// enough for proxies than eight of an eighth (measured at ten level-3 cells near the wall,
// degree 5: 16% of the direct pairs against 19%, for the same error). Children hold the
// points of their part only and get their own tight box. The points are reordered so that
// every cluster's points are one contiguous range [begin, end).
#include <array>
#include <vector>

namespace capsula::fastsum {

/// An axis-aligned box.
struct Box {
  std::array<double, 3> lo{};
  std::array<double, 3> hi{};

  double centre(int axis) const { return 0.5 * (lo[axis] + hi[axis]); }
  /// Half the diagonal: the radius of the sphere about the centre holding the box.
  double radius() const;
};

/// A node of the tree: the points [begin, end) of the tree order and their tight box.
struct Cluster {
  Box box;
  int begin = 0;
  int end = 0;
  int firstChild = -1; ///< children are the clusters [firstChild, firstChild + numChildren)
  int numChildren = 0;
  int level = 0;

  int size() const { return end - begin; }
  bool isLeaf() const { return numChildren == 0; }
};

class Octree {
public:
  Octree() = default;
  /// The tree of n points (structure of arrays); clusters of more than `leafSize` points
  /// are split unless all their points coincide. Throws core::InputError for leafSize < 1.
  Octree(const double* x, const double* y, const double* z, int n, int leafSize);

  /// Clusters, the root first (absent for an empty point set); children follow parents.
  const std::vector<Cluster>& clusters() const { return clusters_; }
  /// order()[k]: the index in the input of the k-th point in tree order.
  const std::vector<int>& order() const { return order_; }
  /// The coordinates in tree order.
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<double>& z() const { return z_; }
  int numPoints() const { return static_cast<int>(order_.size()); }

private:
  Box tightBox(int begin, int end) const;
  void split(int cluster);

  std::vector<Cluster> clusters_;
  std::vector<int> order_;
  std::vector<double> x_, y_, z_;
  int leafSize_ = 1;
};

} // namespace capsula::fastsum
