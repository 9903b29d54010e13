#pragma once
// The second variation of the membrane strain energy with respect to the node positions,
// the tangent stiffness d2E/dx_k dx_l that a linearly implicit time step needs (the
// stiffness the fastest membrane modes decay with). Same energy and notation as
// MembraneEnergyGradient.hpp.
//
// At one quadrature point E_q = W w(I1, I2) is a function of the current metric
// g = (g_11, g_12, g_22), g_ab = g_a . g_b, g_a = sum_k (dphi_k/dxi_a) x_k:
//     I1 = G^11 g_11 + 2 G^12 g_12 + G^22 g_22 - 2,    I2 = (g_11 g_22 - g_12^2) / det G - 1.
// With q_mk = dg_m/dx_k (q_11k = 2 D_1k g_1, q_12k = D_1k g_2 + D_2k g_1, q_22k = 2 D_2k g_2,
// D_ak = dphi_k/dxi_a) and s_mkl I = d2g_m / dx_k dx_l (s_11 = 2 D_1k D_1l,
// s_12 = D_1k D_2l + D_2k D_1l, s_22 = 2 D_2k D_2l):
//     dE_q/dx_k = sum_m Phi_m q_mk,
//     d2E_q/dx_k dx_l = sum_mn Phi_mn q_mk q_nl^T + (sum_m Phi_m s_mkl) I,
// Phi_m = dE_q/dg_m and Phi_mn = d2E_q/dg_m dg_n by the chain rule through (I1, I2).
// The element matrix is symmetric; it annihilates rigid translations, and a rigid
// rotation omega x x maps to omega x F (E invariant under rotations).
#include "capsula/elasticity/MembraneEnergyGradient.hpp"

#include <array>

namespace capsula::elasticity {

/// d2E/dx dx of one element: 18 x 18, row 3 k + i, column 3 l + j (element nodes k, l,
/// coordinates i, j), row-major.
using ElementStiffness = std::array<double, 18 * 18>;

/// Adds the point's share of d2E/dx_k dx_l to `hessian` for the current nodes `x`.
/// Returns false (and adds nothing) where the current tangents are degenerate.
inline bool addEnergyHessian(const ReferenceQuadraturePoint& r, const mesh::ElementNodes& x, const MembraneLaw& law,
                             ElementStiffness& hessian)
{
  mesh::Vec3 g1 = mesh::Vec3::Zero(), g2 = mesh::Vec3::Zero();
  for (int k = 0; k < 6; ++k) {
    g1 += r.dXi[k] * x[k];
    g2 += r.dEta[k] * x[k];
  }
  const double g11 = g1.dot(g1), g12 = g1.dot(g2), g22 = g2.dot(g2);
  const double detg = g11 * g22 - g12 * g12;
  if (!(detg > 0.0)) {
    return false;
  }
  const double* Gi = r.inverseMetric;
  const double detG = 1.0 / (Gi[0] * Gi[2] - Gi[1] * Gi[1]);
  const double I1 = Gi[0] * g11 + 2.0 * Gi[1] * g12 + Gi[2] * g22 - 2.0;
  const double I2 = detg / detG - 1.0;
  const EnergyDerivatives dw = law.energyDerivatives(I1, I2);
  const EnergySecondDerivatives d2w = law.energySecondDerivatives(I1, I2);
  const double W = r.weight;
  // dI/dg_m for m = 11, 12, 22, and the (constant) d2I2/dg dg.
  const double dI1[3] = {Gi[0], 2.0 * Gi[1], Gi[2]};
  const double dI2[3] = {g22 / detG, -2.0 * g12 / detG, g11 / detG};
  const double d2I2[3][3] = {{0.0, 0.0, 1.0 / detG}, {0.0, -2.0 / detG, 0.0}, {1.0 / detG, 0.0, 0.0}};
  double Phi[3], Phi2[3][3];
  for (int m = 0; m < 3; ++m) {
    Phi[m] = W * (dw.dI1 * dI1[m] + dw.dI2 * dI2[m]);
    for (int n = 0; n < 3; ++n) {
      Phi2[m][n] = W * (d2w.dI1dI1 * dI1[m] * dI1[n] + d2w.dI1dI2 * (dI1[m] * dI2[n] + dI2[m] * dI1[n]) +
                        d2w.dI2dI2 * dI2[m] * dI2[n] + dw.dI2 * d2I2[m][n]);
    }
  }
  // q[m][k] and a[n][k] = sum_m Phi_mn q[m][k].
  mesh::Vec3 q[3][6], a[3][6];
  for (int k = 0; k < 6; ++k) {
    q[0][k] = 2.0 * r.dXi[k] * g1;
    q[1][k] = r.dXi[k] * g2 + r.dEta[k] * g1;
    q[2][k] = 2.0 * r.dEta[k] * g2;
  }
  for (int k = 0; k < 6; ++k) {
    for (int n = 0; n < 3; ++n) {
      a[n][k] = Phi2[0][n] * q[0][k] + Phi2[1][n] * q[1][k] + Phi2[2][n] * q[2][k];
    }
  }
  for (int k = 0; k < 6; ++k) {
    for (int l = 0; l < 6; ++l) {
      const double geometric = Phi[0] * 2.0 * r.dXi[k] * r.dXi[l] +
                               Phi[1] * (r.dXi[k] * r.dEta[l] + r.dEta[k] * r.dXi[l]) +
                               Phi[2] * 2.0 * r.dEta[k] * r.dEta[l];
      for (int i = 0; i < 3; ++i) {
        double* row = &hessian[static_cast<std::size_t>((3 * k + i) * 18 + 3 * l)];
        for (int j = 0; j < 3; ++j) {
          row[j] += a[0][k][i] * q[0][l][j] + a[1][k][i] * q[1][l][j] + a[2][k][i] * q[2][l][j];
        }
        row[i] += geometric;
      }
    }
  }
  return true;
}

} // namespace capsula::elasticity
