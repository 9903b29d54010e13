#pragma once
// Spectral Ewald fast sum of the lower wall's Stokeslet (WallStokeslet2P.hpp) in a layer periodic
// in x and z: for sources x_n = (., h_n, .), h_n > 0, with forces g_n and targets x_t, y_t >= 0,
//   u_t = sum_n G^W(x_t, x_n) g_n        (G units: the velocity is u_t / (8 pi mu)),
// zero mode included. A target on a source takes lim (G - G_free) g_n from the source's own
// Stokeslet (SpectralEwald2P.hpp); the image terms never coincide with a target.
//
// With the image points x_n' = (., -h_n, .), d_n = 2 h_n (g_x, -g_y, g_z) and q_n = -2 h_n g_y,
// Blake's system (WallStokeslet2P.hpp) sums as
//   u_t = sum_n [G(x_t - x_n) g_n - G(x_t - x_n') g_n]
//       + y_t sum_n grad (d_n . grad phi)(x_t - x_n')
//       + sum_n [q_n grad phi - e_y (d_n . grad phi)](x_t - x_n'),    phi = 1/r,
// three spectral Ewald sums on one grid (covering the targets and the image points) with the
// engines and the tolerance rule of SpectralEwald2P.hpp: the Stokeslet's over sources and
// images, and two of Laplace derivatives (LaplaceSplit.hpp: local part from f1 and f2, smooth
// multiplier 4 pi e^{-(1 - eta) k^2/(4 xi^2)} / k^2 times i k per derivative, zero mode the
// y-derivatives of the 1D profile -2 pi [y erf(xi' y) + e^{-xi'^2 y^2} / (sqrt(pi) xi')],
// xi' = xi / sqrt(1 - eta)). The cost is that of three N-source sums: N log N.
#include "capsula/ewald/Ewald2PReference.hpp"

#include <vector>

namespace capsula::ewald {

/// u_t = sum_n G^W(x_t, x_n) g_n to the tolerance (header comment); 3 numbers per point and per
/// force; xi <= 0 picks it by the rule of SpectralEwald2P.hpp for the 2N sources and images.
std::vector<double> spectralEwaldWall2P(const PeriodicLayer& layer, double tolerance,
                                        const std::vector<double>& sources, const std::vector<double>& forces,
                                        const std::vector<double>& targets, double xi = 0.0);

} // namespace capsula::ewald
