#pragma once
// The per-node error measure of the treecode near contact (docs/fastsum.md): the largest
// error of one node's velocity 3-vector against a reference, over the reference's largest
// node velocity, max_i |u_i - r_i| / max_i |r_i|.
#include <algorithm>
#include <cmath>
#include <vector>

namespace capsula::fastsum {

inline double largestNodeError(const std::vector<double>& u, const std::vector<double>& reference)
{
  double error = 0.0, size = 0.0;
  for (std::size_t k = 0; k + 2 < u.size(); k += 3) {
    error = std::max(error, std::hypot(u[k] - reference[k], u[k + 1] - reference[k + 1], u[k + 2] - reference[k + 2]));
    size = std::max(size, std::hypot(reference[k], reference[k + 1], reference[k + 2]));
  }
  return error / size;
}

} // namespace capsula::fastsum
