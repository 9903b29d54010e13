#pragma once
// Fast sum of the channel Stokeslet (ChannelStokeslet2P.hpp) in the periodic channel
// 0 < y < H: for sources x_n with heights 0 < h_n < H, forces g_n and targets with
// 0 <= y_t <= H,
//   u_t = sum_n G^C(x_t, x_n) g_n        (G units: the velocity is u_t / (8 pi mu)),
// zero mode included, to the tolerance relative to the largest velocity. A target on a source
// takes lim (G^C - G_free) g_n from that source (SpectralEwaldWall2P.hpp's convention).
//
// The sources split into the lower group (h_n <= H/2) and the upper group (h_n > H/2). The
// lower group's flow is the lower wall's fast sum (SpectralEwaldWall2P.hpp), which has no slip
// on y = 0; the upper group's is the same sum in the reflected frame y -> H - y (positions
// reflected, the y components of forces and velocities flipped), with no slip on y = H. Each
// group's flow is left with a velocity on its far wall, smooth there: its sources and images
// lie at least d = H - max h >= H/2 away, so that the velocity's Fourier coefficients in (x, z)
// decay like e^{-|k| d}. The group's sum samples it on a uniform grid of the far wall (FFT in x
// and z), and the correction is the Stokes flow in the slab that vanishes on the group's own
// wall and cancels it on the far wall, exact per mode (SlabWallFlow.hpp), for the modes
// |k| <= k_c with e^{-k_c d} (1 + k_c d)^2 = tol, gathered at the targets on Chebyshev levels in
// y and a Gaussian-window grid in x and z (SlabFlowGather.hpp). The k = 0 mode (linear in y)
// turns the lower wall's zero mode 8 pi min(y, h) / A into the channel's
// 8 pi min(y, h) (H - max(y, h)) / (H A).
// The cost is that of the two lower-wall sums over N sources and the targets plus the far-wall
// grid, about (k_c L / pi)^2 points (N log N), and of the gather, 3 Ny P^2 per target plus the
// FFTs of Ny levels of the x-z grid.
#include "capsula/ewald/Ewald2PReference.hpp"

#include <vector>

namespace capsula::ewald {

/// u_t = sum_n G^C(x_t, x_n) g_n to the tolerance (header comment); 3 numbers per point and per
/// force; 0 < h_n < H, 0 <= y_t <= H.
std::vector<double> spectralEwaldChannel2P(const PeriodicLayer& layer, double height, double tolerance,
                                           const std::vector<double>& sources, const std::vector<double>& forces,
                                           const std::vector<double>& targets);

} // namespace capsula::ewald
