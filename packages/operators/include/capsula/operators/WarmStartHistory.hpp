#pragma once
// The initial guess of the next Krylov solve of the viscosity-ratio equation (I - K) u = b
// (SecondKindOperator.hpp) from the last few solves of a time integration.
//
// Consecutive right-hand sides of a Runge-Kutta step are O(step) apart, and so are their
// operators. Keeping the last `depth` pairs (b_j, u_j), the guess is
//   u0 = sum_j c_j u_j,   c minimising || b - sum_j c_j b_j ||   (least squares),
// which would be exact if the operator had not changed (A u0 = sum c_j b_j): the residual
// left is what b has outside the span of the b_j plus O(change of A) |u|. The stages of an
// RKF45 step are combinations of the same few slopes, so the span holds most of b; with
// the last solution alone (depth 1: c_1 = the projection of b on b_1) it does not.
// Measured on a level-3 sphere at h/a = 1.6, lambda = 5, 8 RKF45 steps of 1e-3, tolerance
// 1e-9 (double-layer applications per solve): 12.6 from the right-hand side, 9.7 from the
// last solution, 4.4 / 4.1 / 4.8 with depth 4 / 6 / 10 (more columns fit b better but with
// larger coefficients, which amplify the change of the operator).
//
// Everything here is global (3 per node, all nodes, the same on every rank), and every
// rank computes the same guess from the same numbers: no communication, and no dependence
// on the number of ranks beyond what the solutions have. A checkpoint stores it
// (rightHandSides() and solutions() flattened, fromFlattened()), so that a restarted run
// starts its next solve where the uninterrupted run would.
#include <cstddef>
#include <utility>
#include <vector>

namespace capsula::operators {

class WarmStartHistory {
public:
  /// Keeps the last `depth` (>= 1) pairs. Throws core::InputError otherwise.
  explicit WarmStartHistory(int depth = 6);

  int depth() const { return depth_; }
  /// Number of pairs held (0 .. depth()).
  int size() const;
  bool empty() const;
  /// Entries of each stored vector (0 when empty).
  std::size_t length() const;

  /// The guess for right-hand side `rhs` (the length of the stored vectors): the
  /// least-squares combination above; `rhs` itself when nothing is held.
  std::vector<double> initialGuess(const std::vector<double>& rhs) const;

  /// Adds the solved pair (b, u), dropping the oldest beyond depth(). Throws
  /// core::InputError if the lengths differ from each other or from the held pairs.
  void add(std::vector<double> rhs, std::vector<double> solution);

  /// The held right-hand sides and solutions, oldest first, concatenated.
  std::vector<double> rightHandSides() const;
  std::vector<double> solutions() const;
  /// The inverse of the two above (same lengths, a multiple of `length`). Throws
  /// core::InputError naming the problem if they do not fit.
  static WarmStartHistory fromFlattened(int depth, int length, const std::vector<double>& rightHandSides,
                                        const std::vector<double>& solutions);

private:
  int depth_;
  std::vector<std::pair<std::vector<double>, std::vector<double>>> pairs_; // oldest first
};

} // namespace capsula::operators
