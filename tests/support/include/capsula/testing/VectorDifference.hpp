#pragma once
// How far apart two vectors of one quantity are, relative to the larger of its entries.
#include <algorithm>
#include <cmath>
#include <vector>

namespace capsula::testing {

/// max_k |a_k - b_k| / max_k |a_k| (a and b of one size; a not all zero).
inline double relativeDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double scale = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    scale = std::max(scale, std::abs(a[k]));
    difference = std::max(difference, std::abs(a[k] - b[k]));
  }
  return difference / scale;
}

} // namespace capsula::testing
