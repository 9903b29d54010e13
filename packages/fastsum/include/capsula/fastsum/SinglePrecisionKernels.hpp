#pragma once
// The contracted Stokeslet terms of operators/ContractedKernels.hpp in float, for the
// treecode's single-precision sums (SinglePrecisionSums.hpp): u_j += G_ij(x, x0) f_i, x the
// source (integration point), x0 the pole (target), both relative to an origin at height H
// above the wall (ignored in free space), so that x - x0 is formed from small numbers. Same
// formulas (thesis eq 3.11; Blake's wall, App. B.2: G^W = G(xh) - G(X) + 2 h^2 G^D(X) -
// 2 h G^SD(X)), arranged for float vectors: the kernel is bound by square roots and
// divisions, so each distance costs one division (1/r^2) and one square root
// (1/r = sqrt(1/r^2)), and every other power of 1/r is a product. The unit tests pin each
// term to the double one.
//
// SinglePrecisionKernel<Kernel> maps an operators kernel policy to these terms; a kernel
// without a specialisation is summed in double whatever the parameters say.
#include <capsula/greens/PlaneWall.hpp>
#include <capsula/operators/ContractedKernels.hpp>

#include <cmath>

namespace capsula::fastsum {

/// u_j += f_j / r + xh_j (xh . f) / r^3, xh = x - x0 (the free-space Stokeslet).
inline void addFreeSpaceSingleLayerTerm(const float x[3], const float x0[3], const float f[3], float u[3])
{
  const float d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
  const float inv2 = 1.0f / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const float inv1 = std::sqrt(inv2);
  const float df = (d[0] * f[0] + d[1] * f[1] + d[2] * f[2]) * inv1 * inv2;
  for (int j = 0; j < 3; ++j) {
    u[j] += f[j] * inv1 + d[j] * df;
  }
}

/// u_j += G^W_ij f_i (Blake's wall y = 0), as Wall3DKernel::addSingleLayerTerm:
///   G^D_ij f_i = s_j (f_j / R^3 - 3 X_j (X . f) / R^5) =: D_j,
///   G^SD_ij f_i = X_n D_j + s_j (delta_jn (X . f) - f_n X_j) / R^3,
/// X = x - x0' from the image x0' of the pole, h its height, s_j = -1 normal to the wall;
/// the wall is y = -H in the coordinates of x and x0.
inline void addWallSingleLayerTerm(const float x[3], const float x0[3], float H, const float f[3], float u[3])
{
  constexpr int n = greens::wallNormalAxis;
  const float h = x0[n] + H;
  const float d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
  float X[3] = {d[0], d[1], d[2]};
  X[n] = x[n] + h + H;
  const float invr2 = 1.0f / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const float invR2 = 1.0f / (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
  const float invr = std::sqrt(invr2);
  const float invR = std::sqrt(invR2);
  const float invr3 = invr * invr2;
  const float invR3 = invR * invR2;
  const float invR5 = invR3 * invR2;
  const float Xf = X[0] * f[0] + X[1] * f[1] + X[2] * f[2];
  // The free and image Stokeslets with the same association, as in double: for a pole on
  // the wall (h = 0, X = xh) they cancel to the last bit.
  const float free = (d[0] * f[0] + d[1] * f[1] + d[2] * f[2]) * invr3;
  const float image = Xf * invR3;
  for (int j = 0; j < 3; ++j) {
    const float s = j == n ? -1.0f : 1.0f;
    const float dipole = s * (f[j] * invR3 - 3.0f * X[j] * Xf * invR5);
    const float doublet = X[n] * dipole + s * ((j == n ? Xf : 0.0f) - f[n] * X[j]) * invR3;
    u[j] += (f[j] * invr + d[j] * free) - (f[j] * invR + X[j] * image) + 2.0f * h * h * dipole - 2.0f * h * doublet;
  }
}

/// The float terms of a kernel policy, with x and x0 relative to an origin at height H;
/// `available` false: none (the sums stay double).
template <class Kernel>
struct SinglePrecisionKernel {
  static constexpr bool available = false;
};

template <>
struct SinglePrecisionKernel<operators::FreeSpace3DKernel> {
  static constexpr bool available = true;
  static void addSingleLayerTerm(const float x[3], const float x0[3], float /*H*/, const float f[3], float u[3])
  {
    addFreeSpaceSingleLayerTerm(x, x0, f, u);
  }
};

template <>
struct SinglePrecisionKernel<operators::Wall3DKernel> {
  static constexpr bool available = true;
  static void addSingleLayerTerm(const float x[3], const float x0[3], float H, const float f[3], float u[3])
  {
    addWallSingleLayerTerm(x, x0, H, f, u);
  }
};

} // namespace capsula::fastsum
