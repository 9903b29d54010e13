#pragma once
// The hot loops: the regular quadrature sums of eq 3.39 over every quadrature point of a
// range of elements, for a block of targets at once.
//
// The loop over targets is innermost and has no reduction, so it vectorises without
// reassociating floating-point sums (each target adds its terms in source order, the
// same on any number of ranks). Targets sit in a fixed-size block of arrays padded to a
// multiple of the vector width by repeating the last target; the sources are read once
// per point and broadcast. The loops are also compiled for AVX2 and AVX-512
// (core/KernelClones.hpp). The translation units that instantiate these templates need
// -fno-math-errno, or sqrt blocks vectorisation.
#include <capsula/core/KernelClones.hpp>
#include <capsula/operators/KernelTraits.hpp>

#include <algorithm>
#include <type_traits>

namespace capsula::operators {

inline constexpr int targetBlockSize = 128;
inline constexpr int targetLaneMultiple = 8; // the widest vector: 8 doubles

/// Up to targetBlockSize targets (poles) and their running sums.
struct TargetBlock {
  int size = 0;       ///< targets in use
  int paddedSize = 0; ///< size rounded up to targetLaneMultiple
  alignas(64) double x[targetBlockSize];
  alignas(64) double y[targetBlockSize];
  alignas(64) double z[targetBlockSize];
  alignas(64) double sx[targetBlockSize]; ///< density subtracted at the target (double layer)
  alignas(64) double sy[targetBlockSize];
  alignas(64) double sz[targetBlockSize];
  alignas(64) double ux[targetBlockSize]; ///< sums
  alignas(64) double uy[targetBlockSize];
  alignas(64) double uz[targetBlockSize];

  /// Starts a block of n targets: zero sums and subtracted density; call pad() after
  /// filling x, y, z (and sx, sy, sz).
  void start(int n)
  {
    size = n;
    paddedSize = (n + targetLaneMultiple - 1) / targetLaneMultiple * targetLaneMultiple;
    std::fill(ux, ux + targetBlockSize, 0.0);
    std::fill(uy, uy + targetBlockSize, 0.0);
    std::fill(uz, uz + targetBlockSize, 0.0);
    std::fill(sx, sx + targetBlockSize, 0.0);
    std::fill(sy, sy + targetBlockSize, 0.0);
    std::fill(sz, sz + targetBlockSize, 0.0);
  }
  /// Fills the padding lanes with copies of the last target (finite, never used).
  void pad()
  {
    for (int t = size; t < paddedSize; ++t) {
      x[t] = x[size - 1];
      y[t] = y[size - 1];
      z[t] = z[size - 1];
      sx[t] = sx[size - 1];
      sy[t] = sy[size - 1];
      sz[t] = sz[size - 1];
    }
  }
};

/// Sources of the single layer: points and their weighted loads f = <Delta f>_m w h_s.
struct SingleLayerSources {
  const double *x, *y, *z;
  const double *fx, *fy, *fz;
};

/// Sources of the double layer: points, weighted normals a = n w h_s and density v.
struct DoubleLayerSources {
  const double *x, *y, *z;
  const double *ax, *ay, *az;
  const double *vx, *vy, *vz;
};

/// u_t,j += sum_{q in [begin, end)} G_ij(x_q, x_t) f_q,i for every target t of the block.
template <class Kernel>
CAPSULA_KERNEL_CLONES void addSingleLayerSums(const Kernel& kernel, TargetBlock& block, const SingleLayerSources& s,
                                              int begin, int end)
{
  const int n = block.paddedSize;
  for (int q = begin; q < end; ++q) {
    const double x[3] = {s.x[q], s.y[q], s.z[q]};
    const double f[3] = {s.fx[q], s.fy[q], s.fz[q]};
    for (int t = 0; t < n; ++t) {
      const double x0[3] = {block.x[t], block.y[t], block.z[t]};
      double u[3] = {0.0, 0.0, 0.0};
      addSingleLayerTerm(kernel, x, x0, f, u);
      block.ux[t] += u[0];
      block.uy[t] += u[1];
      block.uz[t] += u[2];
    }
  }
}

/// u_t,j += sum_q T_ijk(x_q, x_t) (v_q - s_t)_i a_q,k, with s_t the block's subtracted
/// density if SubtractTargetDensity (the singularity subtraction of eq 3.44), else 0.
template <class Kernel, bool SubtractTargetDensity>
CAPSULA_KERNEL_CLONES void addDoubleLayerSums(const Kernel& kernel, TargetBlock& block, const DoubleLayerSources& s,
                                              int begin, int end)
{
  const int n = block.paddedSize;
  for (int q = begin; q < end; ++q) {
    const double x[3] = {s.x[q], s.y[q], s.z[q]};
    const double a[3] = {s.ax[q], s.ay[q], s.az[q]};
    const double v[3] = {s.vx[q], s.vy[q], s.vz[q]};
    for (int t = 0; t < n; ++t) {
      const double x0[3] = {block.x[t], block.y[t], block.z[t]};
      double density[3] = {v[0], v[1], v[2]};
      if constexpr (SubtractTargetDensity) {
        density[0] -= block.sx[t];
        density[1] -= block.sy[t];
        density[2] -= block.sz[t];
      }
      double u[3] = {0.0, 0.0, 0.0};
      addDoubleLayerTerm(kernel, x, x0, density, a, u);
      block.ux[t] += u[0];
      block.uy[t] += u[1];
      block.uz[t] += u[2];
    }
  }
}

/// The two sums for a policy without state (the built-in ones, the treecode's).
template <class Kernel>
void addSingleLayerSums(TargetBlock& block, const SingleLayerSources& s, int begin, int end)
{
  static_assert(std::is_empty_v<Kernel>, "a policy with state is called through its instance");
  addSingleLayerSums(Kernel{}, block, s, begin, end);
}
template <class Kernel, bool SubtractTargetDensity>
void addDoubleLayerSums(TargetBlock& block, const DoubleLayerSources& s, int begin, int end)
{
  static_assert(std::is_empty_v<Kernel>, "a policy with state is called through its instance");
  addDoubleLayerSums<Kernel, SubtractTargetDensity>(Kernel{}, block, s, begin, end);
}

/// ux_t += sum_q (x_q - x_t) . a_q / |x_q - x_t|^3: the solid angle of the elements.
void addSolidAngleSums(TargetBlock& block, const double* x, const double* y, const double* z, const double* ax,
                       const double* ay, const double* az, int begin, int end);

} // namespace capsula::operators
