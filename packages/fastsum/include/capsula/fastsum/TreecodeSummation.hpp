#pragma once
// The treecode as the far-field back-end of the layer potentials
// (operators/FarFieldSummation.hpp): the regular sums over all quadrature points go to one
// treecode on every source (Treecode.hpp); the singular and near-singular corrections stay
// with the layer potentials, exact.
//
// The double layer's singularity subtraction on a target's own cell (eq 3.44),
//   sum_{q in own cell} T_ijk (v_q - s_t)_i a_q,k,
// is split as sum_q T_ijk v_q,i a_q,k over every source minus s_t,i M_t,ij with
// M_t,ij = sum_{q in own cell} T_ijk a_q,k, the matrix of the constant densities e_i. M
// depends on the geometry only: it is summed once per geometry and target set, by one
// treecode per cell on that cell's sources (three double-layer sums each), and reused by
// every GMRES iteration.
//
// The interaction lists are kept while the targets stay the same (the node targets of
// every evaluation between two geometry updates).
#include <capsula/fastsum/Treecode.hpp>

#include <capsula/operators/FarFieldSummation.hpp>

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

namespace capsula::fastsum {

template <class Kernel>
class TreecodeSummation final : public operators::FarFieldSummation {
public:
  explicit TreecodeSummation(const TreecodeParameters& parameters) : parameters_(parameters), all_(parameters) {}

  std::string name() const override { return "Treecode"; }
  const Treecode<Kernel>& treecode() const { return all_; }

  void setSources(const double* x, const double* y, const double* z, const std::vector<int>& cellPointOffsets) override
  {
    x_ = x;
    y_ = y;
    z_ = z;
    offsets_ = cellPointOffsets;
    all_.setSources(x, y, z, offsets_.empty() ? 0 : offsets_.back());
    targets_.clear();
    ownCellTargets_.clear();
    ownCellTargetCells_.clear();
  }

  void singleLayer(const operators::SingleLayerSources& sources, const double* targets, int n, double* result) override
  {
    useTargets(targets, n);
    all_.singleLayer(sources.fx, sources.fy, sources.fz, result);
  }

  void doubleLayer(const operators::DoubleLayerSources& sources, const double* targets, const int* targetCells,
                   const double* subtracted, int n, double* result) override
  {
    useTargets(targets, n);
    all_.doubleLayer(sources.ax, sources.ay, sources.az, sources.vx, sources.vy, sources.vz, result);
    if (!targetCells) {
      return;
    }
    ownCellMatrices(sources, targets, targetCells, n);
    for (int t = 0; t < n; ++t) {
      const double* M = &ownCell_[9 * static_cast<std::size_t>(t)];
      const double* s = subtracted + 3 * static_cast<std::size_t>(t);
      for (int j = 0; j < 3; ++j) {
        result[3 * t + j] -= s[0] * M[j] + s[1] * M[3 + j] + s[2] * M[6 + j];
      }
    }
  }

private:
  static bool sameValues(const std::vector<double>& kept, const double* values, std::size_t count)
  {
    return kept.size() == count && (count == 0 || std::memcmp(kept.data(), values, count * sizeof(double)) == 0);
  }

  void useTargets(const double* targets, int n)
  {
    const std::size_t count = 3 * static_cast<std::size_t>(n);
    if (!sameValues(targets_, targets, count) || all_.numTargets() != n) {
      targets_.assign(targets, targets + count);
      all_.setTargets(targets, n);
    }
  }

  // ownCell_[9 t + 3 i + j] = M_t,ij for the current geometry and these targets.
  void ownCellMatrices(const operators::DoubleLayerSources& sources, const double* targets, const int* targetCells,
                       int n)
  {
    const std::size_t count = 3 * static_cast<std::size_t>(n);
    if (sameValues(ownCellTargets_, targets, count) && ownCellTargetCells_.size() == static_cast<std::size_t>(n) &&
        std::equal(ownCellTargetCells_.begin(), ownCellTargetCells_.end(), targetCells)) {
      return;
    }
    ownCellTargets_.assign(targets, targets + count);
    ownCellTargetCells_.assign(targetCells, targetCells + n);
    ownCell_.assign(9 * static_cast<std::size_t>(n), 0.0);
    const int numCells = static_cast<int>(offsets_.size()) - 1;
    for (int c = 0; c < numCells; ++c) {
      std::vector<int> members;
      std::vector<double> points;
      for (int t = 0; t < n; ++t) {
        if (targetCells[t] == c) {
          members.push_back(t);
          points.insert(points.end(), targets + 3 * t, targets + 3 * t + 3);
        }
      }
      if (members.empty()) {
        continue;
      }
      const int begin = offsets_[c];
      const int size = offsets_[c + 1] - begin;
      Treecode<Kernel> cell(parameters_);
      cell.setSources(x_ + begin, y_ + begin, z_ + begin, size);
      cell.setTargets(points.data(), static_cast<int>(members.size()));
      const std::vector<double> one(size, 1.0), zero(size, 0.0);
      std::vector<double> column(points.size());
      for (int i = 0; i < 3; ++i) {
        cell.doubleLayer(sources.ax + begin, sources.ay + begin, sources.az + begin, (i == 0 ? one : zero).data(),
                         (i == 1 ? one : zero).data(), (i == 2 ? one : zero).data(), column.data());
        for (std::size_t k = 0; k < members.size(); ++k) {
          for (int j = 0; j < 3; ++j) {
            ownCell_[9 * static_cast<std::size_t>(members[k]) + 3 * i + j] = column[3 * k + j];
          }
        }
      }
    }
  }

  TreecodeParameters parameters_;
  Treecode<Kernel> all_;
  const double *x_ = nullptr, *y_ = nullptr, *z_ = nullptr;
  std::vector<int> offsets_;
  std::vector<double> targets_;
  std::vector<double> ownCellTargets_;
  std::vector<int> ownCellTargetCells_;
  std::vector<double> ownCell_;
};

} // namespace capsula::fastsum
