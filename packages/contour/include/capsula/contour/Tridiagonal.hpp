#pragma once
// O(n) solvers for the (cyclic) tridiagonal systems of cubic-spline fitting
// (thesis eq A.21: "Thomas' algorithm").
#include <vector>

namespace capsula::contour {

/// Solves lower[i] x[i-1] + diagonal[i] x[i] + upper[i] x[i+1] = rhs[i], i = 0..n-1,
/// by the Thomas algorithm (no pivoting: meant for diagonally dominant systems such
/// as the spline equations). lower[0] and upper[n-1] are ignored. The solution
/// overwrites `rhs`. Throws NumericalError on a vanishing pivot.
void solveTridiagonal(const std::vector<double>& lower, const std::vector<double>& diagonal,
                      const std::vector<double>& upper, std::vector<double>& rhs);

/// Solves the cyclic system in which, besides the tridiagonal band, lower[0] multiplies
/// x[n-1] in row 0 and upper[n-1] multiplies x[0] in row n-1 (periodic splines), by the
/// Sherman-Morrison correction of one Thomas solve. Needs n >= 3. The solution
/// overwrites `rhs`.
void solveCyclicTridiagonal(const std::vector<double>& lower, const std::vector<double>& diagonal,
                            const std::vector<double>& upper, std::vector<double>& rhs);

} // namespace capsula::contour
