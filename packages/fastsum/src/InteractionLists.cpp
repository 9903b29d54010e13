#include "capsula/fastsum/InteractionLists.hpp"

#include <cmath>

namespace capsula::fastsum {

namespace {

double centreDistance(const Box& a, const Box& b)
{
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = a.centre(i) - b.centre(i);
    sum += d * d;
  }
  return std::sqrt(sum);
}

void traverse(const Octree& sources, const ClusterProxies& proxies, const Box& batchBox, double theta,
              TargetBatch& batch, InteractionLists& lists)
{
  const auto& clusters = sources.clusters();
  const double batchRadius = batchBox.radius();
  const long long numTargets = static_cast<long long>(batch.targets.size());
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    const Cluster& cluster = clusters[k];
    const bool accepted = batchRadius + cluster.box.radius() < theta * centreDistance(batchBox, cluster.box);
    if (accepted && proxies.hasProxies(k)) {
      batch.proxies.push_back(k);
      lists.usedProxies[k] = 1;
      lists.proxyPairs += numTargets * proxies.pointsPerCluster();
    } else if (accepted || cluster.isLeaf()) {
      batch.direct.push_back(k);
      lists.directPairs += numTargets * cluster.size();
    } else {
      // Children in reverse so that they are visited in tree order.
      for (int c = cluster.numChildren - 1; c >= 0; --c) {
        stack.push_back(cluster.firstChild + c);
      }
    }
  }
}

} // namespace

InteractionLists buildInteractionLists(const Octree& sources, const ClusterProxies& proxies, const double* targets,
                                       int n, double theta, int batchSize)
{
  InteractionLists lists;
  lists.usedProxies.assign(sources.clusters().size(), 0);
  if (n == 0) {
    return lists;
  }
  std::vector<double> x(n), y(n), z(n);
  for (int t = 0; t < n; ++t) {
    x[t] = targets[3 * t];
    y[t] = targets[3 * t + 1];
    z[t] = targets[3 * t + 2];
  }
  const Octree targetTree(x.data(), y.data(), z.data(), n, batchSize);
  for (const Cluster& leaf : targetTree.clusters()) {
    if (!leaf.isLeaf()) {
      continue;
    }
    TargetBatch batch;
    batch.targets.assign(targetTree.order().begin() + leaf.begin, targetTree.order().begin() + leaf.end);
    if (!sources.clusters().empty()) {
      traverse(sources, proxies, leaf.box, theta, batch, lists);
    }
    lists.batches.push_back(std::move(batch));
  }
  return lists;
}

} // namespace capsula::fastsum
