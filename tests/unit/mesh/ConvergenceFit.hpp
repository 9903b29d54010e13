#pragma once
// Observed order of convergence under uniform refinement: the mesh size halves per
// level, so error ~ C h^p gives log2|error| = const - p * level; p is the
// least-squares slope over the levels given.
#include <cmath>
#include <cstddef>
#include <vector>

namespace capsula::mesh::testing {

inline double observedOrder(const std::vector<int>& levels, const std::vector<double>& errors)
{
  const double n = static_cast<double>(levels.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const double x = levels[i];
    const double y = std::log2(std::abs(errors[i]));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace capsula::mesh::testing
