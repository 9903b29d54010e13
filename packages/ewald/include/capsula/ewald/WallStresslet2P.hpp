#pragma once
// Reference sum of the stress of the lower wall's periodic Stokeslet (WallStokeslet2P.hpp), in
// the convention of greens/Wall3D.hpp: T^W_ijk(x, x0) is the stress sigma_ik at x of a force
// along j at x0 = (x0, h, z0) and its images, sigma_ik = T^W_ijk g_j / (8 pi).
//
// Blake's stress image system (greens/PlaneWall.hpp) with X = x - x0', y = x_y, s_j as there:
//   T^W = T(x - x0) - T(X) + 2 h^2 T^D(X) - 2 h T^SD(X)
//       = T(x - x0) - T(X) + 4 h y s_j d_i d_j d_k (1/R) - 4 h s_j (delta_ik d_j d_y - delta_jy d_i d_k)(1/R),
// since T^D_ijk = -2 s_j d_i d_j d_k (1/R), X_y = y + h combines the doublet's X_y T^D with the
// dipole into -2 h y T^D, and the doublet's rest 6 s_j (delta_ik X_j X_y - delta_jy X_i X_k) / R^5
// is 2 s_j (delta_ik d_j d_y - delta_jy d_i d_k)(1/R) (the 1/R^3 parts of X_a X_b / R^5 =
// (d_a d_b (1/R) + delta_ab / R^3) / 3 cancel). The periodic sum is that of the stresslet
// (StressletReference2P.hpp) at x - x0 and X plus the 2P Ewald sums of the second and third
// derivatives of 1/R (LaplaceSplit.hpp).
//
// Zero mode: the y-derivative of the Stokeslet's, -4 pi (sign(y - h) - 1) / A = 8 pi H(h - y) / A
// (H the step) on the entries xxy, xyx, yxx, zzy, zyz, yzz and yyy, 0 elsewhere (the
// derivatives of 1/R average to zero off X_y = 0): the shear mu u' = F / A below the forces and
// none above, and the pressure F_y / A below a normal force.
#include "capsula/ewald/Ewald2PReference.hpp"

namespace capsula::ewald {

/// The periodic sum of d_i d_j d_k (1/R) over the images X + (m L_x, 0, n L_z) (zero mode 0);
/// X not a lattice vector.
void periodicLaplaceThirdDerivatives2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double X[3],
                                       double third[3][3][3]);

/// The periodic wall stresslet T^W[i][j][k](x, x0) (header comment); x0[1] > 0, x[1] >= 0, x not
/// an image of x0.
void periodicWallStresslet2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double x[3],
                             const double x0[3], double T[3][3][3]);

} // namespace capsula::ewald
