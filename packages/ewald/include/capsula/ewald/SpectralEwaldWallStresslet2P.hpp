#pragma once
// Spectral Ewald fast sum of the double layer of the lower wall's periodic stresslet
// (WallStresslet2P.hpp) in a layer periodic in x and z: for sources x_n (heights h_n > 0)
// carrying tensors S_n (S_ik, e.g. q_i n_k w of a double-layer quadrature) and targets x_t,
// y_t >= 0,
//   u_t,j = sum_n T^W_ijk(x_n, x_t) S_n,ik,
// T^W(x, x0) the stress at x of a force at x0 and its images: by reciprocity u is the flow of
// the sources' stresslets, with no slip on y = 0 (T^W vanishes for x0 on the wall). A target
// on a source takes lim (T^W - T_free)(x_n, x_t) S_n there (T_free is odd).
//
// With R = diag(1, -1, 1) and s = (1, -1, 1), WallStresslet2P.hpp's image system at the
// reflected target X_t = R x_t (T odd, d_i d_j d_k (1/r) odd, d_i d_j (1/r) even) reads
//   u_t,j = -U_j(x_t) + U_j(X_t) - 4 y_t [s_j A_j(X_t) + s_j B_j(X_t) + delta_jy C(X_t)],
//   U_j(x) = sum_n T_jik(x - x_n) S_n,ik                 (SpectralEwaldStresslet2P.hpp),
//   A_j(x) = sum_n d_i d_j d_k (1/r)(x - x_n) h_n S_n,ik,
//   B_j(x) = sum_n d_j d_y (1/r)(x - x_n) tr S_n,
//   C(x)   = sum_n d_i d_k (1/r)(x - x_n) S_n,ik,
// all over the sources themselves, so no image point enters: one stresslet sum at the targets
// and their reflections, and two Laplace-derivative sums at the reflections (LaplaceSplit.hpp:
// local part from f1, f2, f3; smooth multiplier 4 pi e^{-(1 - eta) k^2/(4 xi^2)} / k^2 times
// i k_a per derivative; zero mode the yyy entry phi_0''' = 8 xi'^3 sqrt(pi) y e^{-xi'^2 y^2} of
// A and the yy entry phi_0'' = -4 xi' sqrt(pi) e^{-xi'^2 y^2} of B and C). Their zero modes are
// those of the reference: above every source the mean flow is uniform, u_x = 8 pi sum (S_xy +
// S_yx) / A, u_z the same with z, u_y = 8 pi sum tr S / A (a stresslet's slip and a source's
// outflow); below them it is zero.
// The cost is that of three N-source sums: N log N.
#include "capsula/ewald/Ewald2PReference.hpp"

#include <vector>

namespace capsula::ewald {

/// u_t,j = sum_n T^W_ijk(x_n, x_t) S_n,ik to the tolerance (relative to the largest velocity;
/// header comment); tensors hold 9 numbers per source (S_ik at 9 n + 3 i + k), only their
/// symmetric parts enter; h_n > 0, y_t >= 0.
std::vector<double> spectralEwaldWallStresslet2P(const PeriodicLayer& layer, double tolerance,
                                                 const std::vector<double>& sources, const std::vector<double>& tensors,
                                                 const std::vector<double>& targets);

} // namespace capsula::ewald
