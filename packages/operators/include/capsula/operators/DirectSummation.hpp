#pragma once
// The direct far-field back-end: every (target, source) pair in the vectorised loops of
// RegularSums.hpp, O(N M). Targets are cut into blocks of targetBlockSize that never
// straddle a change of target cell, and each target adds its terms in source order, so the
// results are those of the layer potentials' own loops bit for bit.
#include <capsula/operators/FarFieldSummation.hpp>

#include <algorithm>
#include <utility>

namespace capsula::operators {

/// Runs sum(block, cell) on blocks of consecutive targets of one cell (cell -1 when
/// targetCells is null) and writes the block sums to result (what a far-field back-end
/// that sums pairs directly shares).
template <class Sum>
void forTargetBlocks(const double* targets, const int* targetCells, const double* subtracted, int n, double* result,
                     const Sum& sum)
{
  std::vector<int> starts;
  for (int t = 0; t < n; ++t) {
    const bool newCell = targetCells && t > 0 && targetCells[t] != targetCells[t - 1];
    if (starts.empty() || newCell || t - starts.back() == targetBlockSize) {
      starts.push_back(t);
    }
  }
  starts.push_back(n);
  const int numBlocks = static_cast<int>(starts.size()) - 1;
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic)
#endif
  for (int b = 0; b < numBlocks; ++b) {
    const int first = starts[b];
    TargetBlock block;
    block.start(starts[b + 1] - first);
    for (int k = 0; k < block.size; ++k) {
      block.x[k] = targets[3 * (first + k)];
      block.y[k] = targets[3 * (first + k) + 1];
      block.z[k] = targets[3 * (first + k) + 2];
      if (subtracted) {
        block.sx[k] = subtracted[3 * (first + k)];
        block.sy[k] = subtracted[3 * (first + k) + 1];
        block.sz[k] = subtracted[3 * (first + k) + 2];
      }
    }
    block.pad();
    sum(block, targetCells ? targetCells[first] : -1);
    for (int k = 0; k < block.size; ++k) {
      result[3 * (first + k)] = block.ux[k];
      result[3 * (first + k) + 1] = block.uy[k];
      result[3 * (first + k) + 2] = block.uz[k];
    }
  }
}

template <class Kernel>
class DirectSummation final : public FarFieldSummation {
public:
  explicit DirectSummation(Kernel kernel = {}) : kernel_(std::move(kernel)) {}

  std::string name() const override { return "Direct"; }

  void setSources(const double* /*x*/, const double* /*y*/, const double* /*z*/,
                  const std::vector<int>& cellPointOffsets) override
  {
    offsets_ = cellPointOffsets;
  }

  void singleLayer(const SingleLayerSources& sources, const double* targets, int n, double* result) override
  {
    const int numPoints = offsets_.empty() ? 0 : offsets_.back();
    forTargetBlocks(targets, nullptr, nullptr, n, result, [&](TargetBlock& block, int /*cell*/) {
      addSingleLayerSums(kernel_, block, sources, 0, numPoints);
    });
  }

  void doubleLayer(const DoubleLayerSources& sources, const double* targets, const int* targetCells,
                   const double* subtracted, int n, double* result) override
  {
    const int numCells = static_cast<int>(offsets_.size()) - 1;
    forTargetBlocks(targets, targetCells, subtracted, n, result, [&](TargetBlock& block, int cell) {
      for (int d = 0; d < numCells; ++d) {
        if (d == cell) {
          addDoubleLayerSums<Kernel, true>(kernel_, block, sources, offsets_[d], offsets_[d + 1]);
        } else {
          addDoubleLayerSums<Kernel, false>(kernel_, block, sources, offsets_[d], offsets_[d + 1]);
        }
      }
    });
  }

private:
  Kernel kernel_;
  std::vector<int> offsets_;
};

} // namespace capsula::operators
