#pragma once
// Reference sum of the stress of the channel's periodic Stokeslet (ChannelStokeslet2P.hpp), in
// the convention of WallStresslet2P.hpp: T^C_ijk(x, x0) is the stress sigma_ik at x of a force
// along j at x0 (0 < h < H) and its images, sigma_ik = T^C_ijk g_j / (8 pi), that is
//   T^C_ijk = -delta_ik P_j + d_k G^C_ij + d_i G^C_kj,   p = P_j g_j / (8 pi).
// The double layer of a surface in the channel is sum_j T^C_jik(x0, x) n_k q_j (the stress at
// the surface of a force at the target, by reciprocity).
//
// The same Fourier series as the velocity: per mode k != 0, d_x, d_z -> i k_x, i k_z and d_y
// from the profiles' derivatives (W_l to W_l''', W_y to W_y''', T'), and the pressure
// p = (w''' - a^2 w') / a^2 off y = h (from u_l'' - a^2 u_l = i a p with u_l = i w' / a).
// Zero mode: the y-derivative of the velocity's, on xxy, yxx (and zzy, yzz)
//   d_y <G^C>_parallel = 8 pi [(H - h) / H below the force, -h / H above] / A,
// and the pressure of a normal force, which jumps by g_y / A at y = h; its constant is free
// (a uniform pressure exerts no net force on a closed surface) and is chosen with zero mean
// over the height, P_y = 8 pi [step(y - h) - (H - h) / H] / A: symmetric under y -> H - y and,
// as H grows, the lower wall's (no pressure above the force); -P_y goes on xyx, yyy and zyz.
#include "capsula/ewald/Ewald2PReference.hpp"

namespace capsula::ewald {

/// The periodic channel stresslet T^C[i][j][k](x, x0) (header comment) for 0 <= x_y <= H,
/// 0 < x0_y < H, x_y != x0_y, summed to the tolerance (relative to the terms' size).
void periodicChannelStresslet2P(const PeriodicLayer& layer, double height, const double x[3], const double x0[3],
                                double T[3][3][3], double tolerance = 1e-15);

} // namespace capsula::ewald
