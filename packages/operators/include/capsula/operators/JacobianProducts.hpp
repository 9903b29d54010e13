#pragma once
// The products (x, J~ x) that the stage solves of one linearly implicit step have made,
// kept to start the step's later solves from. Every stage and every attempt of a step
// solves with W = I - shift J~ and the same frozen J~ (only the shift changes between
// attempts), so W x = x - shift J~ x is known for every kept x without a new application.
// A solve then starts from the kept x's combination of least residual,
//   c = argmin_c ||r - W X c||_2,   x0 = X c,   r0 = r - W X c,
// and GMRES reduces only what the kept directions cannot reach: the stages' right-hand
// sides differ from one another mostly within the Krylov space the first stage built
// (a stage's slope is f at a point the earlier increments reach, f(y + a u) ~ f(y) + a J~ u).
// This is the minimal-residual projection onto a recycled subspace of GCRO-type methods
// (Parks et al. 2006, SIAM J. Sci. Comput. 28), without the outer orthogonalisation.
#include <cstddef>
#include <vector>

namespace capsula::operators {

class JacobianProducts {
public:
  /// Keeps at most `capacity` products (0: none); when full, a new one replaces the oldest.
  explicit JacobianProducts(std::size_t capacity) : capacity_(capacity) {}

  std::size_t capacity() const { return capacity_; }
  std::size_t size() const { return x_.size(); }

  /// Forgets every product: J~ changed.
  void clear();

  /// Keeps x and J~ x (n numbers each).
  void add(const double* x, const double* Jx, std::size_t n);

  /// The guess x0 = X c of least residual ||r - W X c||_2 with W = I - shift J~, and its
  /// residual r0 = r - W X c (recomputed from the products, not from the projection).
  /// Returns ||r0||_2; with no products, x0 = 0 and r0 = r.
  double minimalResidualGuess(double shift, const std::vector<double>& r, std::vector<double>& x0,
                              std::vector<double>& r0) const;

private:
  std::size_t capacity_;
  std::size_t oldest_ = 0; ///< the slot a new product overwrites once full
  std::vector<std::vector<double>> x_, Jx_;
};

} // namespace capsula::operators
