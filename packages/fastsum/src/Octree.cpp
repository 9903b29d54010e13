#include "capsula/fastsum/Octree.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::fastsum {

double Box::radius() const
{
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double half = 0.5 * (hi[i] - lo[i]);
    sum += half * half;
  }
  return std::sqrt(sum);
}

Octree::Octree(const double* x, const double* y, const double* z, int n, int leafSize) : leafSize_(leafSize)
{
  core::require<core::InputError>(leafSize >= 1, "Octree: the leaf size is ", leafSize, "; it must be >= 1.");
  core::require<core::InputError>(n >= 0, "Octree: ", n, " points.");
  order_.resize(n);
  x_.assign(x, x + n);
  y_.assign(y, y + n);
  z_.assign(z, z + n);
  for (int k = 0; k < n; ++k) {
    order_[k] = k;
  }
  if (n == 0) {
    return;
  }
  Cluster root;
  root.begin = 0;
  root.end = n;
  root.box = tightBox(0, n);
  clusters_.push_back(root);
  // Breadth first: the children of a cluster are appended together, so they are contiguous.
  for (std::size_t c = 0; c < clusters_.size(); ++c) {
    if (clusters_[c].size() > leafSize_) {
      split(static_cast<int>(c));
    }
  }
}

Box Octree::tightBox(int begin, int end) const
{
  Box box;
  const std::vector<double>* coordinates[3] = {&x_, &y_, &z_};
  for (int i = 0; i < 3; ++i) {
    const auto [lo, hi] = std::minmax_element(coordinates[i]->begin() + begin, coordinates[i]->begin() + end);
    box.lo[i] = *lo;
    box.hi[i] = *hi;
  }
  return box;
}

void Octree::split(int index)
{
  const Cluster parent = clusters_[index];
  double longest = 0.0;
  for (int i = 0; i < 3; ++i) {
    longest = std::max(longest, parent.box.hi[i] - parent.box.lo[i]);
  }
  if (longest == 0.0) {
    return; // coinciding points: nothing separates them
  }
  // Halve the longest side (Octree.hpp).
  bool splitAxis[3];
  for (int i = 0; i < 3; ++i) {
    splitAxis[i] = parent.box.hi[i] - parent.box.lo[i] >= longest;
  }
  const std::vector<double>* coordinates[3] = {&x_, &y_, &z_};
  std::vector<int> part(parent.size());
  int counts[8] = {};
  for (int k = parent.begin; k < parent.end; ++k) {
    int code = 0;
    for (int i = 0; i < 3; ++i) {
      if (splitAxis[i] && (*coordinates[i])[k] > parent.box.centre(i)) {
        code |= 1 << i;
      }
    }
    part[k - parent.begin] = code;
    ++counts[code];
  }
  // Counting sort of the range by part, stable (the order within a part is kept).
  int start[8];
  for (int p = 0, sum = parent.begin; p < 8; ++p) {
    start[p] = sum;
    sum += counts[p];
  }
  std::vector<int> newOrder(parent.size());
  std::vector<double> nx(parent.size()), ny(parent.size()), nz(parent.size());
  int next[8];
  std::copy(start, start + 8, next);
  for (int k = parent.begin; k < parent.end; ++k) {
    const int to = next[part[k - parent.begin]]++ - parent.begin;
    newOrder[to] = order_[k];
    nx[to] = x_[k];
    ny[to] = y_[k];
    nz[to] = z_[k];
  }
  std::copy(newOrder.begin(), newOrder.end(), order_.begin() + parent.begin);
  std::copy(nx.begin(), nx.end(), x_.begin() + parent.begin);
  std::copy(ny.begin(), ny.end(), y_.begin() + parent.begin);
  std::copy(nz.begin(), nz.end(), z_.begin() + parent.begin);

  const int firstChild = static_cast<int>(clusters_.size());
  int numChildren = 0;
  for (int p = 0; p < 8; ++p) {
    if (counts[p] == 0) {
      continue;
    }
    Cluster child;
    child.begin = start[p];
    child.end = start[p] + counts[p];
    child.level = parent.level + 1;
    child.box = tightBox(child.begin, child.end);
    clusters_.push_back(child);
    ++numChildren;
  }
  clusters_[index].firstChild = firstChild;
  clusters_[index].numChildren = numChildren;
}

} // namespace capsula::fastsum
