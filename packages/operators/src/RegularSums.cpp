#include "capsula/operators/RegularSums.hpp"

#include <cmath>

namespace capsula::operators {

namespace {

// Clones of a function declared in a header need their definition in every caller's
// translation unit; this one is local and the public function forwards to it.
CAPSULA_KERNEL_CLONES void solidAngleSums(TargetBlock& block, const double* x, const double* y, const double* z,
                                          const double* ax, const double* ay, const double* az, int begin, int end)
{
  const int n = block.paddedSize;
  for (int q = begin; q < end; ++q) {
    const double xq = x[q], yq = y[q], zq = z[q];
    const double a0 = ax[q], a1 = ay[q], a2 = az[q];
    for (int t = 0; t < n; ++t) {
      const double d0 = xq - block.x[t], d1 = yq - block.y[t], d2 = zq - block.z[t];
      const double r2 = d0 * d0 + d1 * d1 + d2 * d2;
      block.ux[t] += (d0 * a0 + d1 * a1 + d2 * a2) / (r2 * std::sqrt(r2));
    }
  }
}

} // namespace

void addSolidAngleSums(TargetBlock& block, const double* x, const double* y, const double* z, const double* ax,
                       const double* ay, const double* az, int begin, int end)
{
  solidAngleSums(block, x, y, z, ax, ay, az, begin, end);
}

} // namespace capsula::operators
