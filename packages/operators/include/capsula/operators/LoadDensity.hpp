#pragma once
// The membrane load Delta f as the single layer integrates it (eq 3.36).
//
// The load is given at the six nodes of every element, 18 numbers per element (element
// after element in the scene's global numbering, node by node in the element's own
// order), and interpolated over the element with its shape functions. One layout serves
// both membrane force methods (elasticity::MembraneForceMethod):
//   - a load constant over each element (the thesis's <Delta f>_m, eq 3.37) repeats the
//     same value at the six nodes: the shape functions sum to one;
//   - a continuous load (virtual work) repeats each node's value in every element that
//     holds it.
// A distinct type, not a bare pointer, so a 3-per-element array cannot be passed by mistake.
#include <cstddef>
#include <utility>
#include <vector>

namespace capsula::operators {

class LoadDensity {
public:
  /// A view of `elementNodeValues` (18 numbers per element), which must outlive it.
  explicit LoadDensity(const double* elementNodeValues) : values_(elementNodeValues) {}

  /// A load constant over each element, from its 3 numbers per element (owns a copy in
  /// the 18-per-element layout).
  static LoadDensity constantOverElements(const std::vector<double>& elementLoads)
  {
    std::vector<double> values(6 * elementLoads.size());
    for (std::size_t m = 0; m < elementLoads.size() / 3; ++m) {
      for (int a = 0; a < 6; ++a) {
        for (int i = 0; i < 3; ++i) {
          values[18 * m + 3 * a + i] = elementLoads[3 * m + i];
        }
      }
    }
    return LoadDensity(std::move(values));
  }

  // Not copyable: a copy of an owning density would point into the original.
  LoadDensity(const LoadDensity&) = delete;
  LoadDensity& operator=(const LoadDensity&) = delete;

  /// Delta f at the six nodes of element m: [3 a + i], a the local node.
  const double* element(int m) const { return values_ + 18 * static_cast<std::size_t>(m); }
  const double* data() const { return values_; }

private:
  explicit LoadDensity(std::vector<double>&& owned) : owned_(std::move(owned)), values_(owned_.data()) {}

  std::vector<double> owned_;
  const double* values_;
};

} // namespace capsula::operators
