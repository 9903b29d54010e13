#pragma once
// The barycentric Lagrange treecode (Wang, Tlupova & Krasny 2020, "A kernel-independent
// treecode based on barycentric Lagrange interpolation", Commun. Comput. Phys. 28) for the
// regular quadrature sums of the Stokes single and double layer of a kernel policy:
//   single  u_t,j = sum_q G_ij(y_q, x_t) f_q,i
//   double  u_t,j = sum_q T_ijk(y_q, x_t) v_q,i a_q,k
// The kernel is only evaluated (at sources and at proxies), never expanded, so free space,
// Blake's wall and any later policy share the code. A far cluster's sum is replaced by the
// sum over its proxies (ClusterProxies.hpp) with interpolated charges: the force f for the
// single layer; for the double layer the 9 products v_i a_k, whose sum over the proxies is
// taken as three double-layer terms with v = e_i and a = (qhat_i1, qhat_i2, qhat_i3).
// Both the direct and the proxy interactions run through the vectorised target blocks of
// operators/RegularSums.hpp (targets innermost, padded); a translation unit instantiating
// this template needs -fno-math-errno like the operators. With parameters.singlePrecision
// the single layer's kernel is evaluated in float (SinglePrecisionSums.hpp); the double
// layer is always double (doubleLayer says why).
//
// Sources: setSources (the geometry: tree, proxy grids). Targets: setTargets (the batches
// and interaction lists, reused by every sum until the next setTargets or setSources).
#include <capsula/fastsum/ClusterProxies.hpp>
#include <capsula/fastsum/InteractionLists.hpp>
#include <capsula/fastsum/Octree.hpp>
#include <capsula/fastsum/SinglePrecisionSums.hpp>
#include <capsula/fastsum/TreecodeParameters.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/operators/RegularSums.hpp>

#include <algorithm>
#include <vector>

namespace capsula::fastsum {

template <class Kernel>
class Treecode {
public:
  explicit Treecode(const TreecodeParameters& parameters) : parameters_(parameters) { validate(parameters_); }

  const TreecodeParameters& parameters() const { return parameters_; }

  /// The source points (structure of arrays); drops the targets.
  void setSources(const double* x, const double* y, const double* z, int n)
  {
    tree_ = Octree(x, y, z, n, parameters_.leafSize);
    proxies_.build(tree_, parameters_.degree);
    lists_ = InteractionLists{};
    numTargets_ = 0;
  }

  /// n targets, 3 coordinates each (x_t, y_t, z_t interleaved).
  void setTargets(const double* targets, int n)
  {
    targets_.assign(targets, targets + 3 * static_cast<std::size_t>(n));
    numTargets_ = n;
    lists_ = buildInteractionLists(tree_, proxies_, targets, n, parameters_.theta, parameters_.batchSize);
  }

  int numSources() const { return tree_.numPoints(); }
  int numTargets() const { return numTargets_; }
  const InteractionLists& interactionLists() const { return lists_; }

  /// u[3 t + j] = sum_q G_ij(y_q, x_t) f_q,i for the targets set; f in the sources' order.
  void singleLayer(const double* fx, const double* fy, const double* fz, double* u)
  {
    sortCharges({fx, fy, fz});
    proxies_.interpolateCharges(tree_, sortedPointers(), lists_.usedProxies, proxyCharges_);
    const operators::SingleLayerSources direct{tree_.x().data(),  tree_.y().data(),  tree_.z().data(),
                                               sorted_[0].data(), sorted_[1].data(), sorted_[2].data()};
    const operators::SingleLayerSources proxy{proxies_.x().data(),     proxies_.y().data(),
                                              proxies_.z().data(),     proxyCharges_[0].data(),
                                              proxyCharges_[1].data(), proxyCharges_[2].data()};
    const auto sum = [](operators::TargetBlock& block, const SinglePrecisionTargets* single,
                        const operators::SingleLayerSources& sources, int begin, int end) {
      if constexpr (SinglePrecisionKernel<Kernel>::available) {
        if (single) {
          addSingleLayerSumsInSinglePrecision<Kernel>(block, *single, sources, begin, end);
          return;
        }
      }
      operators::addSingleLayerSums<Kernel>(block, sources, begin, end);
    };
    const bool inFloat = parameters_.singlePrecision && SinglePrecisionKernel<Kernel>::available;
    evaluate(u, inFloat,
             [&](operators::TargetBlock& block, const SinglePrecisionTargets* single, int cluster, bool viaProxies) {
               if (viaProxies) {
                 const int first = proxies_.offset(cluster);
                 sum(block, single, proxy, first, first + proxies_.pointsPerCluster());
               } else {
                 const Cluster& c = tree_.clusters()[cluster];
                 sum(block, single, direct, c.begin, c.end);
               }
             });
  }

  /// u[3 t + j] = sum_q T_ijk(y_q, x_t) v_q,i a_q,k for the targets set. Always in double:
  /// the double layer is applied inside GMRES (docs/operators.md), which needs a linear
  /// operator to its tolerance (1e-10 by default), and float rounding is not linear at
  /// ~1e-7 (measured: GMRES stops short of 1e-10 with float proxies).
  void doubleLayer(const double* ax, const double* ay, const double* az, const double* vx, const double* vy,
                   const double* vz, double* u)
  {
    const int n = tree_.numPoints();
    sortCharges({ax, ay, az, vx, vy, vz});
    // The 9 charge components v_i a_k of the proxies, component 3 i + k.
    products_.resize(9);
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) {
        products_[3 * i + k].resize(n);
        for (int q = 0; q < n; ++q) {
          products_[3 * i + k][q] = sorted_[3 + i][q] * sorted_[k][q];
        }
      }
    }
    std::vector<const double*> productPointers;
    for (const auto& p : products_) {
      productPointers.push_back(p.data());
    }
    proxies_.interpolateCharges(tree_, productPointers, lists_.usedProxies, proxyCharges_);
    ones_.assign(proxies_.numProxies(), 1.0);
    zeros_.assign(proxies_.numProxies(), 0.0);
    const double* unit = ones_.data();
    const double* zero = zeros_.data();
    const operators::DoubleLayerSources direct{tree_.x().data(),  tree_.y().data(),  tree_.z().data(),
                                               sorted_[0].data(), sorted_[1].data(), sorted_[2].data(),
                                               sorted_[3].data(), sorted_[4].data(), sorted_[5].data()};
    operators::DoubleLayerSources proxy[3];
    for (int i = 0; i < 3; ++i) {
      proxy[i] = {proxies_.x().data(),
                  proxies_.y().data(),
                  proxies_.z().data(),
                  proxyCharges_[3 * i].data(),
                  proxyCharges_[3 * i + 1].data(),
                  proxyCharges_[3 * i + 2].data(),
                  i == 0 ? unit : zero,
                  i == 1 ? unit : zero,
                  i == 2 ? unit : zero};
    }
    evaluate(u, false, [&](operators::TargetBlock& block, const SinglePrecisionTargets*, int cluster, bool viaProxies) {
      if (viaProxies) {
        const int first = proxies_.offset(cluster);
        for (int i = 0; i < 3; ++i) {
          operators::addDoubleLayerSums<Kernel, false>(block, proxy[i], first, first + proxies_.pointsPerCluster());
        }
      } else {
        const Cluster& c = tree_.clusters()[cluster];
        operators::addDoubleLayerSums<Kernel, false>(block, direct, c.begin, c.end);
      }
    });
  }

private:
  // Runs `interact(block, single, cluster, viaProxies)` over every batch's lists and writes
  // the block sums to u; batches of coinciding targets larger than a block are cut. single:
  // the block's targets in float (SinglePrecisionSums.hpp) if inFloat, else null.
  template <class Interact>
  void evaluate(double* u, bool inFloat, const Interact& interact) const
  {
    const int numBatches = static_cast<int>(lists_.batches.size());
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic)
#endif
    for (int b = 0; b < numBatches; ++b) {
      const TargetBatch& batch = lists_.batches[b];
      const int size = static_cast<int>(batch.targets.size());
      for (int first = 0; first < size; first += operators::targetBlockSize) {
        operators::TargetBlock block;
        block.start(std::min(operators::targetBlockSize, size - first));
        for (int k = 0; k < block.size; ++k) {
          const double* x = &targets_[3 * static_cast<std::size_t>(batch.targets[first + k])];
          block.x[k] = x[0];
          block.y[k] = x[1];
          block.z[k] = x[2];
        }
        block.pad();
        SinglePrecisionTargets targets;
        const SinglePrecisionTargets* single = nullptr;
        if (inFloat) {
          targets.assign(block);
          single = &targets;
        }
        for (const int cluster : batch.proxies) {
          interact(block, single, cluster, true);
        }
        for (const int cluster : batch.direct) {
          interact(block, single, cluster, false);
        }
        for (int k = 0; k < block.size; ++k) {
          double* out = u + 3 * static_cast<std::size_t>(batch.targets[first + k]);
          out[0] = block.ux[k];
          out[1] = block.uy[k];
          out[2] = block.uz[k];
        }
      }
    }
  }

  void sortCharges(std::initializer_list<const double*> charges)
  {
    const std::vector<int>& order = tree_.order();
    sorted_.resize(charges.size());
    std::size_t c = 0;
    for (const double* values : charges) {
      sorted_[c].resize(order.size());
      for (std::size_t k = 0; k < order.size(); ++k) {
        sorted_[c][k] = values[order[k]];
      }
      ++c;
    }
  }

  std::vector<const double*> sortedPointers() const
  {
    std::vector<const double*> pointers;
    for (const auto& s : sorted_) {
      pointers.push_back(s.data());
    }
    return pointers;
  }

  TreecodeParameters parameters_;
  Octree tree_;
  ClusterProxies proxies_;
  InteractionLists lists_;
  std::vector<double> targets_;
  int numTargets_ = 0;
  std::vector<std::vector<double>> sorted_, products_, proxyCharges_;
  std::vector<double> ones_, zeros_; // the proxies' unit densities e_i
};

} // namespace capsula::fastsum
