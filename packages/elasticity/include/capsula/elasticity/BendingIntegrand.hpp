#pragma once
// The pointwise integrands of the discrete Helfrich bending energy (HelfrichBending.hpp)
// as functions of the two tangents a_1 = x_xi, a_2 = x_eta of the element map at one
// quadrature point. The element map uses fixed (reference) shape parameters, so a_i is
// linear in the element's nodal positions, a_i = sum_k d_i phi_k x_k, and a derivative
// with respect to x_k is d/da_1 d_xi phi_k + d/da_2 d_eta phi_k: everything below is
// differentiated with respect to the tangents only. Inline and allocation-free.
//
// Notation: g_ij = a_i . a_j, g^ij its inverse, J = |a_1 x a_2| = sqrt(det g),
// n = a_1 x a_2 / J, a^i = g^ij a_j the dual tangents (a^i . a_j = delta_ij).
#include <capsula/mesh/Vec3.hpp>

#include <array>
#include <cmath>

namespace capsula::elasticity {

using mesh::Vec3;

/// Metric quantities at one point of an element map.
struct TangentFrame {
  double J;                 ///< area element: dA = J dxi deta
  Vec3 normal;              ///< n = a_1 x a_2 / J
  double inverse[2][2];     ///< g^ij
  std::array<Vec3, 2> dual; ///< a^1, a^2
};

inline TangentFrame tangentFrame(const Vec3& a1, const Vec3& a2)
{
  TangentFrame f;
  const Vec3 area = a1.cross(a2);
  const double det = area.squaredNorm(); // det g = g11 g22 - g12^2 = |a1 x a2|^2
  f.J = std::sqrt(det);
  f.normal = area / f.J;
  const double g11 = a1.squaredNorm(), g12 = a1.dot(a2), g22 = a2.squaredNorm();
  f.inverse[0][0] = g22 / det;
  f.inverse[0][1] = f.inverse[1][0] = -g12 / det;
  f.inverse[1][1] = g11 / det;
  f.dual[0] = f.inverse[0][0] * a1 + f.inverse[0][1] * a2;
  f.dual[1] = f.inverse[1][0] * a1 + f.inverse[1][1] * a2;
  return f;
}

/// The fixed (non-geometric) fields of the Lagrangian at one quadrature point: the
/// interpolated curvature vector Y_h, multiplier Lambda_h and its parametric derivatives
/// u_i = d_i Lambda_h, the target curvature vector's components (c along n and beta^i
/// along the tangents a_i: R = c n + beta^i a_i, see HelfrichBending.hpp), and k_b.
struct BendingPointFields {
  Vec3 Y;
  Vec3 lambda;
  std::array<Vec3, 2> lambdaDerivative;
  double c;
  double beta[2];
  double modulus;
};

/// d l / d a_1 and d l / d a_2 of the Lagrangian density (per unit parametric area)
///   l = (k_b/2) J |Y - c n - beta^i a_i|^2 + J Lambda.Y - J g^ij u_i . a_j
///     = [(k_b/2)(|Y|^2 + c^2 - 2 beta^i Y.a_i + beta^i beta^j g_ij) + Lambda.Y] J
///       - k_b c Y.(a_1 x a_2) - T,
/// (n is normal to the a_i), whose integral is E + Lambda^T (M Y - K x)
/// (HelfrichBending.cpp). The pieces:
///   dJ/da_k = J a^k,   d[Y.(a_1 x a_2)]/da_1 = a_2 x Y,   .../da_2 = Y x a_1,
///   d[J beta^i Y.a_i]/da_k = (beta^i Y.a_i) J a^k + J beta^k Y,
///   d[J beta^i beta^j g_ij]/da_k = (beta^i beta^j g_ij) J a^k + 2 J beta^k beta^j a_j,
///   T = J g^ij b_ij with b_ij = u_i . a_j:
///   dT/da_k = T a^k - J sum_l (C_kl + C_lk) a_l + J g^ik u_i,  C = g^-1 b g^-1
/// (from d g^ij = -g^ik d g_kl g^lj and d g_kl = da_k . a_l + a_k . da_l).
inline std::array<Vec3, 2> lagrangianTangentDerivative(const Vec3& a1, const Vec3& a2, const TangentFrame& f,
                                                       const BendingPointFields& p)
{
  const Vec3& u1 = p.lambdaDerivative[0];
  const Vec3& u2 = p.lambdaDerivative[1];
  const double(&gi)[2][2] = f.inverse;
  const double b[2][2] = {{u1.dot(a1), u1.dot(a2)}, {u2.dot(a1), u2.dot(a2)}};
  const double T = f.J * (gi[0][0] * b[0][0] + gi[0][1] * (b[0][1] + b[1][0]) + gi[1][1] * b[1][1]);
  double gb[2][2], C[2][2];
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      gb[i][j] = gi[i][0] * b[0][j] + gi[i][1] * b[1][j];
    }
  }
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      C[i][j] = gb[i][0] * gi[0][j] + gb[i][1] * gi[1][j];
    }
  }
  const Vec3 tangential = p.beta[0] * a1 + p.beta[1] * a2; // beta^i a_i
  const double s =
      0.5 * p.modulus * (p.Y.squaredNorm() + p.c * p.c - 2.0 * p.Y.dot(tangential) + tangential.squaredNorm()) +
      p.lambda.dot(p.Y);
  const Vec3 area[2] = {a2.cross(p.Y), p.Y.cross(a1)};
  std::array<Vec3, 2> d;
  for (int k = 0; k < 2; ++k) {
    const Vec3 dT = T * f.dual[k] - f.J * ((C[k][0] + C[0][k]) * a1 + (C[k][1] + C[1][k]) * a2) +
                    f.J * (gi[0][k] * u1 + gi[1][k] * u2);
    d[k] =
        (s * f.J) * f.dual[k] - (p.modulus * p.c) * area[k] - dT + (p.modulus * f.J * p.beta[k]) * (tangential - p.Y);
  }
  return d;
}

} // namespace capsula::elasticity
