#pragma once
// Spreading point densities onto the spectral Ewald grid and gathering a field from it with
// the truncated Gaussians e^{-alpha |x_i - x|^2} (SmoothPartEngine.hpp), P_x P_y P_z grid points
// per point (the support, P = supportPoints or one more along each axis).
//
// The grid is stored with y-levels outermost, then x, then z (index (j N_x + i) N_z + l), so the
// P_z points of one (x, y) row are contiguous but for the periodic wrap in z: each row is cut
// into at most a few contiguous runs, and the loops over a run have no reduction, so they
// vectorise (and are compiled for AVX2 and AVX-512 besides, core/KernelClones.hpp). A gather
// sums the rows of each z offset first and weighs the P_z sums by the z weights last (the
// Gaussian is a product, so this is the same sum in another order).
#include "capsula/ewald/SpectralEwald2P.hpp"

#include <vector>

namespace capsula::ewald::detail {

/// grids[c][index] += G(x_index - x_n) densities[components n + c] for every point x_n of
/// `points` (3 numbers each), G the normalised Gaussian (alpha / pi)^{3/2} e^{-alpha |x|^2}.
void spreadOnGrid(const SpectralEwaldSettings& s, const std::vector<double>& points,
                  const std::vector<double>& densities, int components, double* const* grids);

/// values[3 t + c] += scale sum_index G(x_index - x_t) grids[c][index], c < 3, for every point
/// x_t of `points`.
void gatherFromGrid(const SpectralEwaldSettings& s, const std::vector<double>& points, const double* const* grids,
                    double scale, std::vector<double>& values);

} // namespace capsula::ewald::detail
