#pragma once
// The two lattice sums of a 2P Ewald sum (Ewald2PReference.hpp): the images of a displacement
// within the local cutoff, and the Fourier modes (k_x, k_z) != 0 within the wavenumber cutoff.
#include "capsula/ewald/Ewald2PReference.hpp"

#include <cmath>
#include <stdexcept>

namespace capsula::ewald {

/// visit(shifted) for each xh + (m L_x, 0, n L_z) with |shifted| < rc.
template <class Visit>
void forEachImageWithin(const PeriodicLayer& layer, double rc, const double xh[3], Visit visit)
{
  if (!(layer.lengthX > 0.0) || !(layer.lengthZ > 0.0)) {
    throw std::invalid_argument("ewald: the periods of a 2P layer must be positive");
  }
  // xh folded into [-L/2, L/2) along x and z first, so that few images are looked at.
  const double folded[3] = {xh[0] - layer.lengthX * std::floor(xh[0] / layer.lengthX + 0.5), xh[1],
                            xh[2] - layer.lengthZ * std::floor(xh[2] / layer.lengthZ + 0.5)};
  const int mMax = static_cast<int>(std::ceil(rc / layer.lengthX)) + 1;
  const int nMax = static_cast<int>(std::ceil(rc / layer.lengthZ)) + 1;
  for (int m = -mMax; m <= mMax; ++m) {
    for (int n = -nMax; n <= nMax; ++n) {
      const double shifted[3] = {folded[0] + m * layer.lengthX, folded[1], folded[2] + n * layer.lengthZ};
      if (shifted[0] * shifted[0] + shifted[1] * shifted[1] + shifted[2] * shifted[2] < rc * rc) {
        visit(shifted);
      }
    }
  }
}

/// visit(kx, kz) for each mode 2 pi (m / L_x, n / L_z) != 0 with kx^2 + kz^2 <= kc^2, either all
/// of them or (halfPlane) one of each pair +-(kx, kz).
template <class Visit>
void forEachModeWithin(const PeriodicLayer& layer, double kc, bool halfPlane, Visit visit)
{
  constexpr double pi = 3.14159265358979323846;
  const int mMax = static_cast<int>(std::floor(kc * layer.lengthX / (2.0 * pi)));
  const int nMax = static_cast<int>(std::floor(kc * layer.lengthZ / (2.0 * pi)));
  for (int m = halfPlane ? 0 : -mMax; m <= mMax; ++m) {
    for (int n = -nMax; n <= nMax; ++n) {
      if ((m == 0 && n == 0) || (halfPlane && m == 0 && n < 0)) {
        continue;
      }
      const double kx = 2.0 * pi * m / layer.lengthX;
      const double kz = 2.0 * pi * n / layer.lengthZ;
      if (kx * kx + kz * kz <= kc * kc) {
        visit(kx, kz);
      }
    }
  }
}

} // namespace capsula::ewald
