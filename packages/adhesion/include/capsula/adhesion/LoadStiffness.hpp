#pragma once
// The stiffness K = -dF/dx of nodal forces that act on a membrane from outside (the bonds,
// the wall's repulsion), for the stiff time integrators' Jacobian (scene/VelocityJacobian).
//
// The membrane passes Delta f = -div_s T - f_ext to the fluid (elasticity MembraneMechanics),
// so its nodal load is dE/dx - F and the load's derivative is H + K, with H the tangent
// stiffness of the strain energy. For a conservative force (F = -dU/dx) K is the Hessian of U:
// symmetric, and positive semi-definite where the force pulls back towards a minimum of U.
//
// Kept as entries (row, column, value), rows and columns numbered 3 node + coordinate; an
// entry may come several times and is to be summed (as TangentStiffness::forEachEntry).
#include <cstddef>
#include <vector>

namespace capsula::adhesion {

class LoadStiffness {
public:
  void add(int row, int column, double value)
  {
    rows_.push_back(row);
    columns_.push_back(column);
    values_.push_back(value);
  }
  void clear()
  {
    rows_.clear();
    columns_.clear();
    values_.clear();
  }
  bool empty() const { return values_.empty(); }
  std::size_t numEntries() const { return values_.size(); }

  /// y += K x (3 entries per node).
  void addProduct(const double* x, double* y) const
  {
    for (std::size_t e = 0; e < values_.size(); ++e) {
      y[rows_[e]] += values_[e] * x[columns_[e]];
    }
  }

  /// Calls add(row, column, value) for every entry.
  template <class Add>
  void forEachEntry(Add&& add) const
  {
    for (std::size_t e = 0; e < values_.size(); ++e) {
      add(rows_[e], columns_[e], values_[e]);
    }
  }

private:
  std::vector<int> rows_, columns_;
  std::vector<double> values_;
};

} // namespace capsula::adhesion
