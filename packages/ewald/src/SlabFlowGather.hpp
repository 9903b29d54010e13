#pragma once
// The slab flows of the channel's far-wall correction (SpectralEwaldChannel2P.hpp) summed at
// many targets in O(1) per target: v(x) = sum_k 2 Re(v_k(y) e^{i k.(x, z)}) over the modes
// kept (half of the pairs +-k, k != 0), each v_k(y) a SlabWallFlow.
//
// In y, v is interpolated between Ny Chebyshev-Lobatto levels of [0, H] (barycentric): each
// mode's profile is made of e^{+-a y} and y e^{+-a y}, a <= k_c, whose Chebyshev coefficients,
// relative to the profile's size, are bounded by I_n(z) e^{-z}, z = k_c H / 2, so Ny is the
// first n with I_n(z) e^{-z} below tol / 100, plus 2. In x and z, each level is a trigonometric
// polynomial of degree k_c, gathered as in a type-2 non-uniform FFT with the Gaussian window
// W(r) = e^{-alpha r^2}: the coefficients divided by W^(k) = (pi / alpha) e^{-k^2 / (4 alpha)}
// on a grid of spacing h <= pi / (2 k_c) (two-fold oversampling; inverse FFT), and
// v = h_x h_z sum over the P x P nearest grid points of W(x - x_j) g(x_j). With alpha =
// 2 k_c^2 / ln(1/tol) the aliased copies are below e^{-2 k_c^2 / alpha} = tol and the window's
// truncation below e^{-alpha (P h / 2)^2 + k_c^2 / (4 alpha)} <= tol for P >= 3 ln(1/tol) / pi.
// Per target the cost is 3 Ny P^2; per level that of the inverse FFTs of the grid.
#include "capsula/ewald/Ewald2PReference.hpp"
#include "capsula/ewald/SlabWallFlow.hpp"

#include <utility>
#include <vector>

namespace capsula::ewald {

/// One mode of the correction: its lattice indices (m, n), k = 2 pi (m / L_x, n / L_z), and flow.
struct SlabMode {
  int m = 0;
  int n = 0;
  SlabWallFlow flow;
};

/// u_t += sum over the modes of 2 Re(v_k(y_t) e^{i k.x_t}) to the tolerance (header comment);
/// |k| <= kc for all modes, targets with 0 <= y <= H.
void addSlabFlows(const PeriodicLayer& layer, double height, double kc, double tolerance,
                  const std::vector<SlabMode>& modes, const std::vector<double>& targets, std::vector<double>& u);

} // namespace capsula::ewald
