#include "capsula/contour/UnitGaussLegendre.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>
#include <cstddef>

namespace capsula::contour {

UnitRule unitGaussLegendre(int n)
{
  core::require<core::InputError>(n >= 1 && n <= 64,
                                  "Gauss-Legendre point count must be between 1 and 64, got ", n);
  const double pi = std::acos(-1.0);
  UnitRule rule;
  rule.points.resize(static_cast<std::size_t>(n));
  rule.weights.resize(static_cast<std::size_t>(n));
  // Roots of P_n on [-1, 1] are symmetric: find the positive half by Newton from the
  // asymptotic guess cos(pi (i + 3/4) / (n + 1/2)), then map x -> (1 + x) / 2.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      // Three-term recurrence: (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1}.
      double p0 = 1.0;
      double p1 = x;
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) {
        break;
      }
    }
    const double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
    const auto low = static_cast<std::size_t>(i);
    const auto high = static_cast<std::size_t>(n - 1 - i);
    rule.points[low] = 0.5 * (1.0 - x);
    rule.points[high] = 0.5 * (1.0 + x);
    rule.weights[low] = 0.5 * weight;
    rule.weights[high] = 0.5 * weight;
  }
  return rule;
}

} // namespace capsula::contour
