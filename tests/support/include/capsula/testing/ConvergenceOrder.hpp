#pragma once
// The observed order of convergence of a sequence of errors under refinement, shared
// by the tests that check convergence orders.
#include <cmath>
#include <vector>

namespace capsula::testing {

/// Least-squares slope p of log(error) = c - p log(N): the order at which `error`
/// falls as the number of points or elements N grows.
inline double fittedOrder(const std::vector<int>& n, const std::vector<double>& error)
{
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  const double m = static_cast<double>(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double x = std::log(static_cast<double>(n[i]));
    const double y = std::log(error[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

} // namespace capsula::testing
