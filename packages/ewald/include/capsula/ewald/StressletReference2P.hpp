#pragma once
// Reference 2P Ewald sum of the stresslet (StressletSplit.hpp) in a layer periodic in x and z,
// unbounded in y, as Ewald2PReference.hpp sums the Stokeslet: the stress sigma_ik = T_ijk g_j / (8 pi)
// of a force g per cell at x0 and its images, T_ijk(xh) = -P_j delta_ik + d_k G_ij + d_i G_kj with
// G the periodic Stokeslet. Per mode (kx, kz) != 0 the ky integral of
//   8 pi i gamma^(k) [(delta_il k_j + delta_ij k_l + delta_jl k_i) k^2 - 2 k_i k_j k_l] / k^4
// is a polynomial in ky applied to J0 (ky^n -> (-i d/dy)^n J0, n <= 3). The zero mode is the
// y-derivative of the Stokeslet's: the x-z average of T is -4 pi sign(xh_y) / A on the entries
// with one index y and two equal parallel ones (xxy, xyx, yxx, zzy, zyz, yzz) and on yyy, and 0
// on the others (the pressure's average carries the yyy and the delta_ik parts).
#include "capsula/ewald/Ewald2PReference.hpp"

namespace capsula::ewald {

/// The periodic stresslet T[i][j][k](xh); xh not a lattice vector.
void periodicStresslet2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                         double T[3][3][3]);

/// The local part alone: sum over the images p within r_c of T^R(xh + p; xi).
void periodicStressletReal2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                             double T[3][3][3]);

/// The smooth part alone, zero mode included.
void periodicStressletFourier2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                                double T[3][3][3]);

} // namespace capsula::ewald
