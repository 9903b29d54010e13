#include <capsula/quadrature/GaussLegendre.hpp>

#include <capsula/core/Error.hpp>

#include <cmath>
#include <limits>

namespace capsula::quadrature {
namespace {

struct LegendreValue {
  double value;      // P_n(t)
  double derivative; // P_n'(t)
};

// P_n and P_n' by the three-term recurrence (k+1) P_{k+1} = (2k+1) t P_k - k P_{k-1}.
LegendreValue legendre(int n, double t)
{
  double previous = 1.0; // P_0
  double current = t;    // P_1
  for (int k = 1; k < n; ++k) {
    const double next = ((2 * k + 1) * t * current - k * previous) / (k + 1);
    previous = current;
    current = next;
  }
  // P_n' = n (t P_n - P_{n-1}) / (t^2 - 1); the nodes lie strictly inside (-1, 1).
  return {current, n * (t * current - previous) / (t * t - 1.0)};
}

} // namespace

Rule1D gaussLegendre(int n, double a, double b)
{
  core::require<core::InputError>(n >= 1, "Gauss-Legendre order n = ", n, " is invalid; use n >= 1.");
  core::require<core::InputError>(std::isfinite(a) && std::isfinite(b) && a < b, "Gauss-Legendre interval [", a, ", ",
                                  b, "] is invalid; use finite a < b.");
  const double pi = std::acos(-1.0);
  const double eps = std::numeric_limits<double>::epsilon();
  const double centre = 0.5 * (a + b);
  const double halfLength = 0.5 * (b - a);

  Rule1D rule;
  rule.points.assign(n, 0.0);
  rule.weights.assign(n, 0.0);
  // Roots come in +-t pairs: find the positive ones (largest first) and mirror them, so the
  // rule is exactly symmetric. For odd n the middle root is t = 0.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double t = std::cos(pi * (i + 0.75) / (n + 0.5)); // Tricomi's first approximation
    if (2 * i + 1 == n) {
      t = 0.0;
    } else {
      bool converged = false;
      for (int iteration = 0; iteration < 100 && !converged; ++iteration) {
        const LegendreValue p = legendre(n, t);
        const double step = p.value / p.derivative;
        t -= step;
        converged = std::abs(step) <= 4.0 * eps; // |t| < 1: an absolute test
      }
      core::require<core::NumericalError>(converged, "Newton's method did not converge for root ", i,
                                          " of the Legendre polynomial of order ", n, ".");
    }
    const double derivative = legendre(n, t).derivative;
    const double weight = 2.0 / ((1.0 - t * t) * derivative * derivative);
    rule.points[n - 1 - i] = centre + halfLength * t;
    rule.points[i] = centre - halfLength * t;
    rule.weights[n - 1 - i] = halfLength * weight;
    rule.weights[i] = halfLength * weight;
  }
  return rule;
}

} // namespace capsula::quadrature
