#include "capsula/fastsum/ClusterProxies.hpp"

#include "capsula/fastsum/BarycentricLagrange.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::fastsum {

void ClusterProxies::build(const Octree& tree, int degree)
{
  core::require<core::InputError>(degree >= 1 && degree <= maxInterpolationDegree, "Treecode degree ", degree,
                                  " must lie in [1, ", maxInterpolationDegree, "].");
  degree_ = degree;
  const int m = degree + 1;
  pointsPerCluster_ = m * m * m;
  const auto& clusters = tree.clusters();
  offset_.assign(clusters.size(), -1);
  x_.clear();
  y_.clear();
  z_.clear();
  nodes_.clear();
  int next = 0;
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    if (clusters[k].size() <= pointsPerCluster_) {
      continue;
    }
    offset_[k] = next;
    next += pointsPerCluster_;
    double s[3][maxInterpolationDegree + 1];
    for (int axis = 0; axis < 3; ++axis) {
      chebyshevPoints(degree, clusters[k].box.lo[axis], clusters[k].box.hi[axis], s[axis]);
      nodes_.insert(nodes_.end(), s[axis], s[axis] + m);
    }
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) {
        for (int l = 0; l < m; ++l) {
          x_.push_back(s[0][i]);
          y_.push_back(s[1][j]);
          z_.push_back(s[2][l]);
        }
      }
    }
  }
}

// P2M: charges[c][first + p] += sum_{q in [begin, end)} L_p(y_q) q_q,c (eq 14).
void ClusterProxies::addPointCharges(const Octree& tree, const double* nodes, int begin, int end,
                                     const std::vector<const double*>& sourceCharges, int first,
                                     std::vector<std::vector<double>>& charges) const
{
  const int m = degree_ + 1;
  const double* coordinates[3] = {tree.x().data(), tree.y().data(), tree.z().data()};
  double basis[3][maxInterpolationDegree + 1];
  double outer[(maxInterpolationDegree + 1) * (maxInterpolationDegree + 1)];
  for (int q = begin; q < end; ++q) {
    for (int axis = 0; axis < 3; ++axis) {
      lagrangeBasis(degree_, nodes + axis * m, coordinates[axis][q], basis[axis]);
    }
    // The tensor product L_i L_j L_l, formed as (L_i L_j) then times L_l: m^2 + m^3 products.
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) {
        outer[i * m + j] = basis[0][i] * basis[1][j];
      }
    }
    for (std::size_t c = 0; c < sourceCharges.size(); ++c) {
      const double charge = sourceCharges[c][q];
      double* out = charges[c].data() + first;
      for (int ij = 0; ij < m * m; ++ij) {
        const double w = outer[ij] * charge;
        for (int l = 0; l < m; ++l) {
          out[ij * m + l] += w * basis[2][l];
        }
      }
    }
  }
}

// M2M: the parent's charges += sum_k L_p(s_k) qhat_k over the child's proxies s_k. The
// basis is a tensor product on tensor grids, so the sum runs one axis at a time:
// 3 m^4 products per component instead of m^6.
void ClusterProxies::addChildCharges(const double* parentNodes, const double* childNodes, int childFirst, int first,
                                     std::vector<std::vector<double>>& charges) const
{
  const int m = degree_ + 1;
  const int mm = m * m;
  // L[axis][a * m + i] = L_a(s_i): the parent's basis at the child's nodes.
  std::vector<double> L(3 * static_cast<std::size_t>(mm));
  for (int axis = 0; axis < 3; ++axis) {
    for (int i = 0; i < m; ++i) {
      double values[maxInterpolationDegree + 1];
      lagrangeBasis(degree_, parentNodes + axis * m, childNodes[axis * m + i], values);
      for (int a = 0; a < m; ++a) {
        L[axis * mm + a * m + i] = values[a];
      }
    }
  }
  std::vector<double> once(static_cast<std::size_t>(pointsPerCluster_)), twice(once.size());
  for (auto& component : charges) {
    const double* child = component.data() + childFirst;
    // once[a][j][l] = sum_i L_a(s_i,x) child[i][j][l]
    for (int a = 0; a < m; ++a) {
      for (int jl = 0; jl < mm; ++jl) {
        double sum = 0.0;
        for (int i = 0; i < m; ++i) {
          sum += L[a * m + i] * child[i * mm + jl];
        }
        once[a * mm + jl] = sum;
      }
    }
    // twice[a][b][l] = sum_j L_b(s_j,y) once[a][j][l]
    for (int a = 0; a < m; ++a) {
      for (int b = 0; b < m; ++b) {
        for (int l = 0; l < m; ++l) {
          double sum = 0.0;
          for (int j = 0; j < m; ++j) {
            sum += L[mm + b * m + j] * once[a * mm + j * m + l];
          }
          twice[a * mm + b * m + l] = sum;
        }
      }
    }
    // parent[a][b][c] += sum_l L_c(s_l,z) twice[a][b][l]
    double* parent = component.data() + first;
    for (int ab = 0; ab < mm; ++ab) {
      for (int c = 0; c < m; ++c) {
        double sum = 0.0;
        for (int l = 0; l < m; ++l) {
          sum += L[2 * mm + c * m + l] * twice[ab * m + l];
        }
        parent[ab * m + c] += sum;
      }
    }
  }
}

void ClusterProxies::interpolateCharges(const Octree& tree, const std::vector<const double*>& sourceCharges,
                                        const std::vector<char>& used, std::vector<std::vector<double>>& charges) const
{
  charges.resize(sourceCharges.size());
  for (auto& component : charges) {
    component.resize(x_.size());
  }
  const int m = degree_ + 1;
  const auto& clusters = tree.clusters();
  // A cluster's charges are needed if it is used or an ancestor is (its charges pass up).
  // Parents precede their children in the tree's order.
  std::vector<char> needed(clusters.size(), 0);
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    needed[k] = static_cast<char>(needed[k] || (offset_[k] >= 0 && used[k]));
    for (int c = 0; c < clusters[k].numChildren; ++c) {
      needed[clusters[k].firstChild + c] = needed[k];
    }
  }
  // Upward: a cluster takes its children's proxy charges (M2M) where they have proxies and
  // their points (P2M) where they have none, so each point is interpolated once.
  for (std::size_t k = clusters.size(); k-- > 0;) {
    if (offset_[k] < 0 || !needed[k]) {
      continue;
    }
    const int first = offset_[k];
    const double* nodes = &nodes_[3 * m * static_cast<std::size_t>(first / pointsPerCluster_)];
    for (auto& component : charges) {
      std::fill(component.begin() + first, component.begin() + first + pointsPerCluster_, 0.0);
    }
    const Cluster& cluster = clusters[k];
    if (cluster.isLeaf()) {
      addPointCharges(tree, nodes, cluster.begin, cluster.end, sourceCharges, first, charges);
    }
    for (int c = cluster.firstChild; c < cluster.firstChild + cluster.numChildren; ++c) {
      if (offset_[c] >= 0) {
        const double* childNodes = &nodes_[3 * m * static_cast<std::size_t>(offset_[c] / pointsPerCluster_)];
        addChildCharges(nodes, childNodes, offset_[c], first, charges);
      } else {
        addPointCharges(tree, nodes, clusters[c].begin, clusters[c].end, sourceCharges, first, charges);
      }
    }
  }
}

} // namespace capsula::fastsum
