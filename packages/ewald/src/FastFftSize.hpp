#pragma once
// FFTW's fast transform sizes, shared by the spectral Ewald grids and the channel's gather.
#include <algorithm>

namespace capsula::ewald::detail {

/// The smallest n' >= n whose prime factors are 2, 3, 5 and 7.
inline int fastFftSize(int n)
{
  for (int m = std::max(n, 1);; ++m) {
    int rest = m;
    for (int p : {2, 3, 5, 7}) {
      while (rest % p == 0) {
        rest /= p;
      }
    }
    if (rest == 1) {
      return m;
    }
  }
}

} // namespace capsula::ewald::detail
