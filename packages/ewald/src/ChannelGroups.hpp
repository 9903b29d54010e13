#pragma once
// The channel's fast sums (SpectralEwaldChannel2P.hpp, SpectralEwaldChannelStresslet2P.hpp)
// from a fast sum above one wall: the sources split into the lower group (h_n <= H/2) and
// the upper group (h_n > H/2); each group's flow is its own wall's sum (the upper group's in
// the reflected frame y -> H - y), left with a velocity on its far wall, smooth there (its
// sources lie at least d = H - max h >= H/2 away, so that the velocity's Fourier coefficients
// in (x, z) decay like e^{-|k| d}). The group's sum samples that velocity on a uniform grid of
// the far wall (FFT in x and z), and the correction is the Stokes flow in the slab that
// vanishes on the group's own wall and cancels it on the far wall, exact per mode
// (SlabWallFlow.hpp), for the modes |k| <= k_c with e^{-k_c d} (1 + k_c d)^2 = tol, gathered
// at the targets by SlabFlowGather.hpp. The mode k = 0 is linear in y: V y / H.
#include "capsula/ewald/Ewald2PReference.hpp"

#include <functional>
#include <vector>

namespace capsula::ewald::detail {

/// The fast sum above the wall y = 0: the velocities at `points` of `sources` carrying
/// `densities` (a fixed number per source).
using WallSum = std::function<std::vector<double>(
    const std::vector<double>& sources, const std::vector<double>& densities, const std::vector<double>& points)>;

/// One source's density in the frame reflected by y -> H - y (in place).
using DensityReflection = std::function<void(double* density)>;

/// u_t = the channel's sum (header comment) of sources (0 < h_n < H) carrying `components`
/// numbers of density each, at targets 0 <= y_t <= H; the velocities' y components flip in the
/// reflected frame.
std::vector<double> channelSum(const PeriodicLayer& layer, double height, double tolerance,
                               const std::vector<double>& sources, const std::vector<double>& densities, int components,
                               const std::vector<double>& targets, const WallSum& wallSum,
                               const DensityReflection& reflectDensity);

} // namespace capsula::ewald::detail
