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

void ClusterProxies::interpolateCharges(const Octree& tree, const std::vector<const double*>& sourceCharges,
                                        const std::vector<char>& used, std::vector<std::vector<double>>& charges) const
{
  const int numComponents = static_cast<int>(sourceCharges.size());
  charges.resize(numComponents);
  for (auto& component : charges) {
    component.resize(x_.size());
  }
  const int m = degree_ + 1;
  const auto& clusters = tree.clusters();
  const double* coordinates[3] = {tree.x().data(), tree.y().data(), tree.z().data()};
  int grid = 0; // index of the cluster's grid among those with proxies
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    if (offset_[k] < 0) {
      continue;
    }
    const double* s = &nodes_[3 * m * grid++];
    if (!used[k]) {
      continue;
    }
    const int first = offset_[k];
    for (int c = 0; c < numComponents; ++c) {
      std::fill(charges[c].begin() + first, charges[c].begin() + first + pointsPerCluster_, 0.0);
    }
    double basis[3][maxInterpolationDegree + 1];
    double outer[(maxInterpolationDegree + 1) * (maxInterpolationDegree + 1)];
    for (int q = clusters[k].begin; q < clusters[k].end; ++q) {
      for (int axis = 0; axis < 3; ++axis) {
        lagrangeBasis(degree_, s + axis * m, coordinates[axis][q], basis[axis]);
      }
      // The tensor product L_i L_j L_l, formed as (L_i L_j) then times L_l: m^2 + m^3 products.
      for (int i = 0; i < m; ++i) {
        for (int j = 0; j < m; ++j) {
          outer[i * m + j] = basis[0][i] * basis[1][j];
        }
      }
      for (int c = 0; c < numComponents; ++c) {
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
}

} // namespace capsula::fastsum
