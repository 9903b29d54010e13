#include "capsula/fastsum/BarycentricLagrange.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>

namespace capsula::fastsum {

void chebyshevPoints(int degree, double a, double b, double* s)
{
  core::require<core::InputError>(degree >= 1 && degree <= maxInterpolationDegree, "Interpolation degree ", degree,
                                  " must lie in [1, ", maxInterpolationDegree, "].");
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  for (int k = 0; k <= degree; ++k) {
    s[k] = mid + half * std::cos(M_PI * k / degree);
  }
  // Exact ends: a source on the box face must meet the end point exactly.
  s[0] = b;
  s[degree] = a;
}

void lagrangeBasis(int degree, const double* s, double x, double* values)
{
  double sum = 0.0;
  for (int k = 0; k <= degree; ++k) {
    const double difference = x - s[k];
    if (difference == 0.0) {
      for (int l = 0; l <= degree; ++l) {
        values[l] = l == k ? 1.0 : 0.0;
      }
      return;
    }
    const double weight = (k % 2 == 0 ? 1.0 : -1.0) * (k == 0 || k == degree ? 0.5 : 1.0);
    values[k] = weight / difference;
    sum += values[k];
  }
  const double scale = 1.0 / sum;
  for (int k = 0; k <= degree; ++k) {
    values[k] *= scale;
  }
}

} // namespace capsula::fastsum
