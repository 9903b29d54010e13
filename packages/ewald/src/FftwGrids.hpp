#pragma once
// FFTW's arrays and fast transform sizes, shared by the spectral Ewald engines and the
// channel's far-wall transforms.
#include <fftw3.h>

#include <algorithm>
#include <cstddef>
#include <memory>

namespace capsula::ewald::detail {

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};
using RealGrid = std::unique_ptr<double[], FftwFree>;
using ComplexGrid = std::unique_ptr<fftw_complex[], FftwFree>;

/// A real grid, zeroed when it accumulates (the spread sources) and not when FFTW overwrites it.
inline RealGrid makeRealGrid(std::size_t size, bool zeroed)
{
  RealGrid grid(static_cast<double*>(fftw_malloc(sizeof(double) * size)));
  if (zeroed) {
    std::fill(grid.get(), grid.get() + size, 0.0);
  }
  return grid;
}

/// A complex grid (FFTW's output, not zeroed).
inline ComplexGrid makeComplexGrid(std::size_t size)
{
  return ComplexGrid(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * size)));
}

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
