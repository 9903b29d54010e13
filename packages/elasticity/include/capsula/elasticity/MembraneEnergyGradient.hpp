#pragma once
// The gradient of the membrane strain energy with respect to the node positions: the
// nodal forces of the principle of virtual work (the finite-element membrane of
// Walter, Salsac, Barthes-Biesel & Le Tallec 2010, on the thesis's quadratic elements).
//
//     E = sum_m int_{E_m^0} w(I1, I2) dS0,    dE/dx_k = sum over the elements holding k.
//
// In material coordinates (xi, eta) (the REFERENCE shape parameters, eq 3.17), with
// g_a = dx/dxi_a the current and G_a the reference tangents, g_ab = g_a . g_b and G^ab the
// inverse reference metric:
//     I1 = G^ab g_ab - 2,            dI1/dx_k = 2 G^ab (dphi_k/dxi_a) g_b,
//     J^2 = det g / det G = I2 + 1,  dI2/dx_k = 2 J^2 g^ab (dphi_k/dxi_a) g_b,
// the invariants of eq 3.29 (tr C = tr B, det C = det B). The element's own C0 geometry
// is used, with no nodal averaging, so sum_k dE/dx_k = 0 and sum_k x_k x dE/dx_k = 0
// exactly (E is invariant under translations and rotations).
#include "capsula/elasticity/MembraneLaw.hpp"

#include <capsula/mesh/ElementGeometry.hpp>

#include <cmath>

namespace capsula::elasticity {

/// What the energy gradient needs of one quadrature point of the reference element.
struct ReferenceQuadraturePoint {
  double dXi[6];           ///< dphi_k/dxi at the point (reference shape parameters)
  double dEta[6];          ///< dphi_k/deta
  double inverseMetric[3]; ///< G^11, G^12, G^22
  double weight;           ///< w_q H_s: the reference area the point stands for
};

/// The reference data of one point: `X` the reference nodes, `p` their shape parameters.
inline ReferenceQuadraturePoint referenceQuadraturePoint(const mesh::ElementNodes& X, const mesh::ShapeParameters& p,
                                                         double xi, double eta, double ruleWeight)
{
  ReferenceQuadraturePoint r;
  mesh::shapeFunctionDerivatives(p, xi, eta, r.dXi, r.dEta);
  mesh::Vec3 G1 = mesh::Vec3::Zero(), G2 = mesh::Vec3::Zero();
  for (int k = 0; k < 6; ++k) {
    G1 += r.dXi[k] * X[k];
    G2 += r.dEta[k] * X[k];
  }
  const double G11 = G1.dot(G1), G12 = G1.dot(G2), G22 = G2.dot(G2);
  const double det = G11 * G22 - G12 * G12;
  r.inverseMetric[0] = G22 / det;
  r.inverseMetric[1] = -G12 / det;
  r.inverseMetric[2] = G11 / det;
  r.weight = ruleWeight * std::sqrt(det);
  return r;
}

/// Adds the point's share of dE/dx_k to gradient[k] (k = 0..5, the element's nodes) for
/// the current nodes `x`, and returns its share of E. Returns NaN (and adds nothing)
/// where the current tangents are degenerate (det g <= 0: a crushed element).
inline double addEnergyGradient(const ReferenceQuadraturePoint& r, const mesh::ElementNodes& x, const MembraneLaw& law,
                                mesh::Vec3 gradient[6])
{
  mesh::Vec3 g1 = mesh::Vec3::Zero(), g2 = mesh::Vec3::Zero();
  for (int k = 0; k < 6; ++k) {
    g1 += r.dXi[k] * x[k];
    g2 += r.dEta[k] * x[k];
  }
  const double g11 = g1.dot(g1), g12 = g1.dot(g2), g22 = g2.dot(g2);
  const double detg = g11 * g22 - g12 * g12;
  if (!(detg > 0.0)) {
    return std::nan("");
  }
  const double* Gi = r.inverseMetric;
  const double detG = 1.0 / (Gi[0] * Gi[2] - Gi[1] * Gi[1]);
  const double J2 = detg / detG;
  const double I1 = Gi[0] * g11 + 2.0 * Gi[1] * g12 + Gi[2] * g22 - 2.0;
  const double I2 = J2 - 1.0;
  const EnergyDerivatives dw = law.energyDerivatives(I1, I2);
  // dE/dx_k = 2 W [dw1 G^ab + dw2 J^2 g^ab] dphi_k/dxi_a g_b = dphi_k/dxi a_1 + dphi_k/deta a_2.
  const double c1 = 2.0 * r.weight * dw.dI1;
  const double c2 = 2.0 * r.weight * dw.dI2 * J2 / detg; // g^ab = adj(g)/det g
  const double m11 = c1 * Gi[0] + c2 * g22;
  const double m12 = c1 * Gi[1] - c2 * g12;
  const double m22 = c1 * Gi[2] + c2 * g11;
  const mesh::Vec3 a1 = m11 * g1 + m12 * g2;
  const mesh::Vec3 a2 = m12 * g1 + m22 * g2;
  for (int k = 0; k < 6; ++k) {
    gradient[k] += r.dXi[k] * a1 + r.dEta[k] * a2;
  }
  return r.weight * law.energyDensity(I1, I2);
}

} // namespace capsula::elasticity
