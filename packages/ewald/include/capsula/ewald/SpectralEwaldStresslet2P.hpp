#pragma once
// Spectral Ewald fast sum of the stresslet (StressletSplit.hpp) in a layer periodic in x and z,
// unbounded in y, with the machinery and the tolerance rule of SpectralEwald2P.hpp: for sources
// x_n carrying tensors S_n (S_jk, e.g. q_j n_k w of a double-layer quadrature),
//   u_t = sum_n T_ijk(x_t - x_n) S_n,jk,
// T the periodic stresslet of StressletReference2P.hpp (its zero mode included). T is symmetric
// in j and k, so only the symmetric part of S enters. A target on a source takes from it
// lim (T - T_free) S_n, the field of its images (T^F is odd: its value at the pole is zero).
// Local part: T^R over the images within r_c. Smooth part: the multiplier
//   8 pi i gamma_eta(k) [2 (S k)_i + k_i tr S - 2 k_i (k.S.k) / k^2] / k^2,
// gamma_eta = (1 + k^2/(4 xi^2)) e^{-(1 - eta) k^2/(4 xi^2)}; zero mode: 2 S_iy K(y) on the
// parallel components and tr(S) K(y) on y, K the y-derivative of the Stokeslet's 1D profile.
#include "capsula/ewald/SpectralEwald2P.hpp"

#include <vector>

namespace capsula::ewald {

/// u_t = sum_n T_ijk(x_t - x_n) S_n,jk to the tolerance; tensors hold 9 numbers per source
/// (S_jk at 9 n + 3 j + k); xi <= 0 picks it by the rule of SpectralEwald2P.hpp.
std::vector<double> spectralEwaldStresslet2P(const PeriodicLayer& layer, double tolerance,
                                             const std::vector<double>& sources, const std::vector<double>& tensors,
                                             const std::vector<double>& targets, double xi = 0.0);

} // namespace capsula::ewald
