#pragma once
// The cluster-particle traversal of the treecode (Wang, Tlupova & Krasny 2020, Section 3.3
// and Algorithm 1): the targets are grouped into batches (the leaves of an octree on the
// targets), and each batch walks the source tree from the root. A cluster C seen from a
// batch B is
//   - approximated by its proxies if (r_B + r_C) / R < theta (R the distance of the box
//     centres) and C has proxies (more sources than a proxy grid);
//   - summed directly if it is a leaf, or if it passes the test but is too small for proxies;
//   - otherwise opened: its children are tested in turn.
// The lists depend on the geometry only: the same targets reuse them at every evaluation.
#include <capsula/fastsum/ClusterProxies.hpp>
#include <capsula/fastsum/Octree.hpp>

#include <vector>

namespace capsula::fastsum {

struct TargetBatch {
  std::vector<int> targets; ///< indices into the caller's target list
  std::vector<int> proxies; ///< source clusters taken through their proxies
  std::vector<int> direct;  ///< source clusters summed point by point
};

struct InteractionLists {
  std::vector<TargetBatch> batches;
  std::vector<char> usedProxies; ///< per source cluster: some batch takes its proxies
  long long directPairs = 0;     ///< (target, source) kernel evaluations per sum
  long long proxyPairs = 0;      ///< (target, proxy) kernel evaluations per charge component set
};

/// The lists for n targets (3 coordinates each) against the source tree with its proxies;
/// batches hold at most batchSize targets. theta = 0 makes every interaction direct.
InteractionLists buildInteractionLists(const Octree& sources, const ClusterProxies& proxies, const double* targets,
                                       int n, double theta, int batchSize);

} // namespace capsula::fastsum
