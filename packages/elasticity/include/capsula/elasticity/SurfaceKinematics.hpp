#pragma once
// Kinematics of a membrane surface (thesis eqs 3.26-3.29, 3.33-3.35).
//
// The surface deformation gradient A maps the reference tangent plane onto the current
// one: A X_xi = x_xi, A X_eta = x_eta, A N = 0 (eqs 3.33-3.35). With the dual
// (contravariant) reference tangents G^xi, G^eta (G^a . X_b = delta_ab, G^a . N = 0)
// the solution is explicit, A = x_xi G^xi^T + x_eta G^eta^T: no 3x3 inverse.
// B = A A^T (eq 3.28) has eigenvalues lambda1^2, lambda2^2 in the current tangent plane
// and 0 along the current normal n. All functions are inline and allocation-free.
#include <capsula/mesh/Vec3.hpp>

#include <array>
#include <cmath>

namespace capsula::elasticity {

using mesh::Mat3;
using mesh::Vec3;

/// G^xi, G^eta: the dual basis of the tangents (X_xi, X_eta) in their own plane.
inline std::array<Vec3, 2> dualTangents(const Vec3& tangentXi, const Vec3& tangentEta)
{
  const Vec3 areaVector = tangentXi.cross(tangentEta); // H N
  const double h2 = areaVector.squaredNorm();
  return {tangentEta.cross(areaVector) / h2, areaVector.cross(tangentXi) / h2};
}

/// A = x_xi G^xi^T + x_eta G^eta^T (eqs 3.33-3.35); `dual` from dualTangents() of the
/// reference tangents at the same material point.
inline Mat3 surfaceDeformationGradient(const Vec3& currentXi, const Vec3& currentEta, const std::array<Vec3, 2>& dual)
{
  return currentXi * dual[0].transpose() + currentEta * dual[1].transpose();
}

/// P = I - n n^T, the projector onto the tangent plane of unit normal n.
inline Mat3 tangentProjector(const Vec3& n)
{
  return Mat3::Identity() - n * n.transpose();
}

/// v rotated by the smallest rotation that takes unit vector `from` onto unit vector
/// `to` (Rodrigues, axis from x to). Carries a tangent vector of one plane into a
/// nearby plane; requires from . to > -1.
inline Vec3 rotateOnto(const Vec3& v, const Vec3& from, const Vec3& to)
{
  const Vec3 axis = from.cross(to); // sin(theta) times the unit axis
  const double c = from.dot(to);    // cos(theta)
  const Vec3 kv = axis.cross(v);
  return v + kv + axis.cross(kv) / (1.0 + c);
}

/// An orthonormal pair (e1, e2) spanning the plane normal to unit vector n, with
/// e1 x e2 = n.
inline std::array<Vec3, 2> tangentBasis(const Vec3& n)
{
  // Cross with the coordinate axis least aligned with n: never nearly parallel.
  Vec3 axis = Vec3::Zero();
  int k = 0;
  n.cwiseAbs().minCoeff(&k);
  axis[k] = 1.0;
  const Vec3 e1 = axis.cross(n).normalized();
  return {e1, n.cross(e1)};
}

/// Principal stretches lambda1 >= lambda2 > 0 (eq 3.28).
struct PrincipalStretches {
  double major;
  double minor;
  double areaRatio() const { return major * minor; } ///< J = dS/dS0 = lambda1 lambda2
};

/// Square roots of the eigenvalues of B in the plane normal to n (B n = 0 assumed):
/// the 2x2 block in a tangent basis, smaller root from det / larger (no cancellation).
inline PrincipalStretches principalStretches(const Mat3& B, const Vec3& n)
{
  const auto e = tangentBasis(n);
  const Vec3 b1 = B * e[0];
  const double b11 = e[0].dot(b1), b12 = e[1].dot(b1), b22 = e[1].dot(B * e[1]);
  const double mean = 0.5 * (b11 + b22);
  const double radius = std::hypot(0.5 * (b11 - b22), b12);
  const double largest = mean + radius;
  const double smallest = (b11 * b22 - b12 * b12) / largest;
  return {std::sqrt(largest), std::sqrt(smallest)};
}

/// I1 = lambda1^2 + lambda2^2 - 2, I2 = lambda1^2 lambda2^2 - 1 (eq 3.29).
struct StrainInvariants {
  double I1;
  double I2;
};

inline StrainInvariants strainInvariants(const PrincipalStretches& s)
{
  const double l1 = s.major * s.major, l2 = s.minor * s.minor;
  return {l1 + l2 - 2.0, l1 * l2 - 1.0};
}

} // namespace capsula::elasticity
