#pragma once
// Reference sum of the Stokeslet above the no-slip plane y = 0 in a layer periodic in x and z
// (periods L_x, L_z, area A = L_x L_z), in the convention of greens/Wall3D.hpp: a force g per
// cell at x0 = (x0, h, z0), h > 0, and at its images gives u(x) = G^W_ij(x, x0) g_j / (8 pi mu).
//
// Blake's image system (greens/PlaneWall.hpp) written with free-space singularities at the
// mirror point x0' = (x0, -h, z0), X = x - x0', R = |X|, y = x_y, s_j = -1 for j = y, else +1:
//   G^W_ij = G_ij(x - x0) - G_ij(X) + 2 h^2 G^D_ij(X) - 2 h G^SD_ij(X)
//          = G_ij(x - x0) - G_ij(X) + 2 h y s_j d_i d_j (1/R) + 2 h s_j (delta_jy d_i - delta_iy d_j)(1/R),
// since G^D_ij = -s_j d_i d_j (1/R), the doublet's X_y G^D with X_y = y + h combines with the
// dipole into -2 h y G^D, and its rest is s_j (delta_jy X_i - delta_iy X_j) / R^3 with
// X_i / R^3 = -d_i (1/R). The factors y and h do not depend on x and z, so the periodic sum is
// that of the two Stokeslets (Ewald2PReference.hpp, Hasimoto's split) plus that of the first
// and second derivatives of 1/R (LaplaceSplit.hpp, Ewald's Gaussian split), each a 2P Ewald
// sum with its own zero mode.
//
// Zero mode. The x-z average of the Laplace sum is -2 pi |X_y| / A, so d_y (1/R) averages to
// -2 pi / A (X_y = y + h > 0 in the fluid) and its other first and all second derivatives to
// zero; the doublet's average terms cancel between delta_jy d_i and delta_iy d_j. The average
// of the two Stokeslets, -4 pi (|y - h| - (y + h)) / A on the parallel components, is
//   <G^W>_parallel = 8 pi min(y, h) / A,   <G^W>_y. = <G^W>_.y = 0,
// the 1D problem mu u'' = -(g / A) delta(y - h), u(0) = 0, u'(infinity) = 0: a net force F
// parallel to the wall drives u(y) = c F min(y, h) / (mu A) with c = 1 (u' jumps by
// -F / (mu A) at y = h), and a normal force drives no mean flow (the wall carries it).
// The constant of the free-space convention cancels between the source and its image, and the
// lattice sum of G^W converges absolutely (G^W ~ h y / rho^3 far along the wall), so this
// Ewald sum equals the plain image sum of Blake's tensor.
#include "capsula/ewald/Ewald2PReference.hpp"

namespace capsula::ewald {

/// <G^W>_parallel * A = 8 pi min(y, h) (header comment), y >= 0, h > 0.
double wallZeroModeProfile(double y, double h);

/// The periodic sum of d_i (1/R) (gradient) and d_i d_j (1/R) (hessian) over the images
/// X + (m L_x, 0, n L_z), zero modes -2 pi sign(X_y) / A and 0 included (header comment);
/// X not a lattice vector.
void periodicLaplaceDerivatives2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double X[3],
                                  double gradient[3], double hessian[3][3]);

/// The periodic wall Stokeslet G^W_ij(x, x0) (header comment); x0[1] > 0, x[1] >= 0, x not an
/// image of x0.
void periodicWallStokeslet2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double x[3],
                             const double x0[3], double G[3][3]);

} // namespace capsula::ewald
