#pragma once
// The proxy particles of the source clusters: a tensor grid of Chebyshev points on each
// cluster's box, and the proxy charges interpolated onto it (Wang, Tlupova & Krasny 2020,
// eq 14):
//   qhat_k = sum_{y_q in C} L_k1(y_q,1) L_k2(y_q,2) L_k3(y_q,3) q_q,
// so that sum_q K(x, y_q) q_q ~ sum_k K(x, s_k) qhat_k for a target x far from C, for any
// kernel K smooth in y on the box. The charges may have several components (3 for a
// force, 9 for the double layer's v_i a_k); each is interpolated alike.
#include <capsula/fastsum/Octree.hpp>

#include <vector>

namespace capsula::fastsum {

class ClusterProxies {
public:
  /// Proxy grids of degree `degree` on the clusters of `tree` with more points than a grid
  /// has (only they are worth replacing).
  void build(const Octree& tree, int degree);

  int degree() const { return degree_; }
  /// (degree + 1)^3.
  int pointsPerCluster() const { return pointsPerCluster_; }
  bool hasProxies(int cluster) const { return offset_[cluster] >= 0; }
  /// First proxy of the cluster in x(), y(), z() and in the charge arrays.
  int offset(int cluster) const { return offset_[cluster]; }
  int numProxies() const { return static_cast<int>(x_.size()); }
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<double>& z() const { return z_; }

  /// charges[c][offset(k) + p] = qhat_p of component c for every cluster k with proxies
  /// and used[k] != 0, and for their descendants with proxies (others left as they are);
  /// sourceCharges[c] in the tree's order. Upward: a cluster's charges are interpolated
  /// from its children's proxies, exact for the polynomial basis (a degree-n polynomial is
  /// its own interpolant on the child's grid), so each point is interpolated once.
  void interpolateCharges(const Octree& tree, const std::vector<const double*>& sourceCharges,
                          const std::vector<char>& used, std::vector<std::vector<double>>& charges) const;

private:
  void addPointCharges(const Octree& tree, const double* nodes, int begin, int end,
                       const std::vector<const double*>& sourceCharges, int first,
                       std::vector<std::vector<double>>& charges) const;
  void addChildCharges(const double* parentNodes, const double* childNodes, int childFirst, int first,
                       std::vector<std::vector<double>>& charges) const;

  int degree_ = 0;
  int pointsPerCluster_ = 0;
  std::vector<int> offset_;
  std::vector<double> x_, y_, z_;
  std::vector<double> nodes_; // per cluster with proxies: 3 (degree + 1) Chebyshev points
};

} // namespace capsula::fastsum
