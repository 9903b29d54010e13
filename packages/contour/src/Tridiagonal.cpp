#include "capsula/contour/Tridiagonal.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>
#include <cstddef>

namespace capsula::contour {

void solveTridiagonal(const std::vector<double>& lower, const std::vector<double>& diagonal,
                      const std::vector<double>& upper, std::vector<double>& rhs)
{
  const std::size_t n = diagonal.size();
  core::require<core::InputError>(lower.size() == n && upper.size() == n && rhs.size() == n,
                                  "solveTridiagonal: the bands and the right-hand side must all "
                                  "have ",
                                  n, " entries");
  if (n == 0) {
    return;
  }
  // Forward elimination keeps the modified super-diagonal in `c`; back substitution
  // then runs in place on `rhs`.
  std::vector<double> c(n, 0.0);
  double pivot = diagonal[0];
  core::require<core::NumericalError>(pivot != 0.0, "solveTridiagonal: zero pivot in row 0");
  c[0] = upper[0] / pivot;
  rhs[0] /= pivot;
  for (std::size_t i = 1; i < n; ++i) {
    pivot = diagonal[i] - lower[i] * c[i - 1];
    core::require<core::NumericalError>(pivot != 0.0 && std::isfinite(pivot),
                                        "solveTridiagonal: zero or non-finite pivot in row ", i);
    c[i] = (i + 1 < n) ? upper[i] / pivot : 0.0;
    rhs[i] = (rhs[i] - lower[i] * rhs[i - 1]) / pivot;
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    rhs[i] -= c[i] * rhs[i + 1];
  }
}

void solveCyclicTridiagonal(const std::vector<double>& lower, const std::vector<double>& diagonal,
                            const std::vector<double>& upper, std::vector<double>& rhs)
{
  const std::size_t n = diagonal.size();
  core::require<core::InputError>(n >= 3, "solveCyclicTridiagonal: needs at least 3 unknowns, got ", n);
  core::require<core::InputError>(lower.size() == n && upper.size() == n && rhs.size() == n,
                                  "solveCyclicTridiagonal: the bands and the right-hand side must "
                                  "all have ",
                                  n, " entries");
  // A = T + u v^T with u = (g, 0.., 0, alpha), v = (1, 0.., 0, beta/g): the corners
  // beta = A(0, n-1) and alpha = A(n-1, 0) move into a rank-one term; g = -A(0,0)
  // keeps the modified diagonal away from cancellation.
  const double beta = lower[0];
  const double alpha = upper[n - 1];
  const double g = -diagonal[0];
  std::vector<double> modified = diagonal;
  modified[0] -= g;
  modified[n - 1] -= alpha * beta / g;

  std::vector<double> z(n, 0.0);
  z[0] = g;
  z[n - 1] = alpha;
  solveTridiagonal(lower, modified, upper, rhs);
  solveTridiagonal(lower, modified, upper, z);

  const double vDotY = rhs[0] + beta / g * rhs[n - 1];
  const double vDotZ = z[0] + beta / g * z[n - 1];
  const double denominator = 1.0 + vDotZ;
  core::require<core::NumericalError>(denominator != 0.0, "solveCyclicTridiagonal: singular cyclic system");
  const double factor = vDotY / denominator;
  for (std::size_t i = 0; i < n; ++i) {
    rhs[i] -= factor * z[i];
  }
}

} // namespace capsula::contour
