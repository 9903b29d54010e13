#pragma once
// The treecode's single-layer sums in single precision: the loop of
// operators/RegularSums.hpp with the kernel evaluated in float (SinglePrecisionKernels.hpp),
// for tolerances loose enough to absorb the rounding.
//
// Why: the sums are bound by the square roots and divisions of the kernel; a float vector
// holds twice the lanes of a double one and float sqrt and division cost less per lane.
// Rounding: each term is off by a few float ulps (~6e-8 relative) if its separation
// x - x0 is, so the coordinates are rounded relative to the centre of the target block
// (subtracted in double, then rounded): x - x0 is then off by ~6e-8 of the distance from
// that centre, not from the coordinate origin. Measured on spheres near the wall with every
// pair in float: 1.3e-7 relative in the single layer (docs/fastsum.md). The float sums of
// one interaction (one cluster) are added to the block's double sums, so round-off does not
// grow with the number of clusters. Only the single layer: the double layer is applied
// inside GMRES, which needs a linear operator (Treecode.hpp).
#include <capsula/fastsum/SinglePrecisionKernels.hpp>

#include <capsula/operators/RegularSums.hpp>

#include <algorithm>

namespace capsula::fastsum {

/// The widest float vector: 16 lanes.
inline constexpr int singleLaneMultiple = 16;

/// The targets of an operators::TargetBlock in float, relative to `origin`.
struct SinglePrecisionTargets {
  int size = 0;
  int paddedSize = 0; ///< size rounded up to singleLaneMultiple
  double origin[3] = {0.0, 0.0, 0.0};
  alignas(64) float x[operators::targetBlockSize];
  alignas(64) float y[operators::targetBlockSize];
  alignas(64) float z[operators::targetBlockSize];

  /// The block's targets, relative to the centre of their box. The origin is a float
  /// value: then a pole on the wall (height 0) has the float height -origin exactly, and
  /// Blake's image cancels its pole to the last bit, as in double (the kernel vanishes).
  void assign(const operators::TargetBlock& block)
  {
    size = block.size;
    paddedSize = (size + singleLaneMultiple - 1) / singleLaneMultiple * singleLaneMultiple;
    const double* coordinates[3] = {block.x, block.y, block.z};
    float* rounded[3] = {x, y, z};
    for (int axis = 0; axis < 3; ++axis) {
      const auto [lo, hi] = std::minmax_element(coordinates[axis], coordinates[axis] + size);
      origin[axis] = static_cast<double>(static_cast<float>(0.5 * (*lo + *hi)));
      for (int t = 0; t < paddedSize; ++t) {
        // Padding lanes repeat the last target (finite, never read back).
        rounded[axis][t] = static_cast<float>(coordinates[axis][std::min(t, size - 1)] - origin[axis]);
      }
    }
  }
};

/// block.u_t,j += sum_{q in [begin, end)} G_ij(x_q, x_t) f_q,i, the kernel in float.
template <class Kernel>
CAPSULA_KERNEL_CLONES void
addSingleLayerSumsInSinglePrecision(operators::TargetBlock& block, const SinglePrecisionTargets& targets,
                                    const operators::SingleLayerSources& s, int begin, int end)
{
  const int n = targets.paddedSize;
  alignas(64) float ux[operators::targetBlockSize] = {};
  alignas(64) float uy[operators::targetBlockSize] = {};
  alignas(64) float uz[operators::targetBlockSize] = {};
  const double* o = targets.origin;
  const float H = static_cast<float>(o[greens::wallNormalAxis]);
  for (int q = begin; q < end; ++q) {
    const float x[3] = {static_cast<float>(s.x[q] - o[0]), static_cast<float>(s.y[q] - o[1]),
                        static_cast<float>(s.z[q] - o[2])};
    const float f[3] = {static_cast<float>(s.fx[q]), static_cast<float>(s.fy[q]), static_cast<float>(s.fz[q])};
    for (int t = 0; t < n; ++t) {
      const float x0[3] = {targets.x[t], targets.y[t], targets.z[t]};
      float u[3] = {0.0f, 0.0f, 0.0f};
      SinglePrecisionKernel<Kernel>::addSingleLayerTerm(x, x0, H, f, u);
      ux[t] += u[0];
      uy[t] += u[1];
      uz[t] += u[2];
    }
  }
  for (int t = 0; t < targets.size; ++t) {
    block.ux[t] += static_cast<double>(ux[t]);
    block.uy[t] += static_cast<double>(uy[t]);
    block.uz[t] += static_cast<double>(uz[t]);
  }
}

} // namespace capsula::fastsum
