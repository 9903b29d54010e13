#pragma once
// Reference sum of the Stokeslet in the periodic channel 0 < y < H between two no-slip walls,
// periodic in x and z (periods L_x, L_z, area A = L_x L_z), in the convention of
// WallStokeslet2P.hpp: a force g per cell at x0 = (x0, h, z0), 0 < h < H, gives
// u(x) = G^C_ij(x, x0) g_j / (8 pi mu).
//
// The exact Fourier series in (x, z) (the periodic form of Liron & Mochon 1976): per mode
// k = (k_x, k_z) != 0, a = |k|, the flow of mu (u'' - a^2 u) - (i k p, p') = -g delta(y - h) with
// u = 0 on y = 0 and y = H, e^{i k.(x - x0)} understood. Along t = (-k_z, k_x) / a the
// component u_t = g_t T(y) with the Dirichlet Green's function of d^2 - a^2,
//   T = [e^{-a|y-h|} - e^{-a(y+h)} - e^{-a(2H-y-h)} + e^{-a(2H-|y-h|)}] / (2 a (1 - e^{-2aH})).
// In the plane of k and e_y, w = u_y solves (d^2 - a^2)^2 w = 0 off y = h, with w, w' continuous,
// [w''] = i a g_l and [w'''] = a^2 g_y at y = h (g_l = g.k / a; from [u_l'] = -g_l, [p] = g_y,
// u_l = i w' / a, p = (w''' - a^2 w') / a^2), and w = w' = 0 on both walls:
//   w = i a g_l W_l + a^2 g_y W_y,   u_l = -g_l W_l' + i a g_y W_y',
// W = F(y - h) + (c1 + c2 y) e^{-a y} + (c3 + c4 (H - y)) e^{-a (H - y)}, the free part
// F = Phi' = -t e^{-a|t|} / (4a) for W_l and F = Phi = (1 + a|t|) e^{-a|t|} / (4 a^3) for W_y
// (Phi the Green's function of (d^2 - a^2)^2), c1..c4 from no slip (a 4 x 4 system).
// The mode k = 0 (the zero mode) is u'' = -g_parallel delta(y - h) / A, no slip on both walls:
//   <G^C>_parallel = 8 pi min(y, h) (H - max(y, h)) / (H A),   all other entries 0,
// which tends to the lower wall's 8 pi min(y, h) / A as H grows; a normal force drives no
// mean flow (the walls carry it).
// The terms decay like e^{-a |y - h|}: the sum stops at a_c with e^{-a_c d} (1 + a_c d)^3 = tol,
// d = |y - h|, so it serves targets away from the source's height (cost ~ (L / d)^2 modes).
#include "capsula/ewald/Ewald2PReference.hpp"

namespace capsula::ewald {

/// <G^C>_parallel * A = 8 pi min(y, h) (H - max(y, h)) / H (header comment), 0 <= y <= H, 0 < h < H.
double channelZeroModeProfile(double y, double h, double height);

/// The wavenumber a_c where the channel series stops for |y - h| = distance (header comment).
double channelSeriesCutoff(double distance, double tolerance);

/// The periodic channel Stokeslet G^C_ij(x, x0) (header comment) for 0 <= x_y <= H, 0 < x0_y < H,
/// x_y != x0_y, summed to the tolerance (relative to the terms' size).
void periodicChannelStokeslet2P(const PeriodicLayer& layer, double height, const double x[3], const double x0[3],
                                double G[3][3], double tolerance = 1e-15);

} // namespace capsula::ewald
