#pragma once
// Fast sum of the double layer of the channel's periodic stresslet (ChannelStresslet2P.hpp) in
// the periodic channel 0 < y < H: for sources x_n with heights 0 < h_n < H carrying tensors S_n
// and targets with 0 <= y_t <= H,
//   u_t,j = sum_n T^C_ijk(x_n, x_t) S_n,ik,
// to the tolerance relative to the largest velocity: the flow of the sources' stresslets with no
// slip on both walls (T^C(x, x0) is the stress at x of a force at x0). A target on a source
// takes lim (T^C - T_free)(x_n, x_t) S_n there.
//
// The channel's groups (the lower and the upper half's sources, each summed above its own wall
// by SpectralEwaldWallStresslet2P.hpp, the upper one in the frame y -> H - y where S_ik becomes
// s_i s_k S_ik, s = (1, -1, 1)) with the far-wall slab correction of SpectralEwaldChannel2P.hpp.
// Zero mode: a group's mean flow above its sources, u_par = 8 pi sum (S_py + S_yp) / A and
// u_y = 8 pi sum tr S / A, is cancelled on the far wall by the linear V y / H, which gives the
// reference's: -c y / H below the sources, c (H - y) / H above them (for u_y the reference's
// pressure convention, with zero mean over the height; sum tr S = 0 for the double layer of a
// closed surface's velocity, whose flux through the surface is zero).
// The cost is that of the two wall sums plus the far-wall grid and gather: N log N.
#include "capsula/ewald/Ewald2PReference.hpp"

#include <vector>

namespace capsula::ewald {

/// u_t,j = sum_n T^C_ijk(x_n, x_t) S_n,ik to the tolerance (header comment); tensors hold 9
/// numbers per source (S_ik at 9 n + 3 i + k); 0 < h_n < H, 0 <= y_t <= H.
std::vector<double> spectralEwaldChannelStresslet2P(const PeriodicLayer& layer, double height, double tolerance,
                                                    const std::vector<double>& sources,
                                                    const std::vector<double>& tensors,
                                                    const std::vector<double>& targets);

} // namespace capsula::ewald
