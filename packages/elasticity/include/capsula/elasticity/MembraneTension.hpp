#pragma once
// Cauchy tension of a hyperelastic membrane (thesis eq 3.30):
//     T = 2/(lambda1 lambda2) [ dw/dI1 B + lambda1^2 lambda2^2 dw/dI2 (I - n n) ],
// a symmetric tensor in the current tangent plane (force per unit current length).
// Its eigenvalues there are T_i = 2/J (dw/dI1 lambda_i^2 + J^2 dw/dI2), J = lambda1
// lambda2, which equal (1/lambda_j) dw/dlambda_i (i != j): the principal tensions of
// the law written in stretches. Inline and allocation-free.
#include "capsula/elasticity/MembraneLaw.hpp"
#include "capsula/elasticity/SurfaceKinematics.hpp"

#include <algorithm>

namespace capsula::elasticity {

/// T (eq 3.30) from B = A A^T, the current unit normal n, the principal stretches of
/// B and the law's derivatives at their invariants.
inline Mat3 membraneTension(const Mat3& B, const Vec3& n, const PrincipalStretches& s, const EnergyDerivatives& dw)
{
  const double J = s.areaRatio();
  return (2.0 / J) * (dw.dI1 * B + (J * J * dw.dI2) * tangentProjector(n));
}

/// The two in-plane eigenvalues of T, major >= minor (minor < 0: compression, the
/// seed of wrinkling/buckling without bending stiffness, thesis Section 3.7).
struct PrincipalTensions {
  double major;
  double minor;
};

inline PrincipalTensions principalTensions(const PrincipalStretches& s, const EnergyDerivatives& dw)
{
  const double J = s.areaRatio();
  const double t1 = (2.0 / J) * (dw.dI1 * s.major * s.major + J * J * dw.dI2);
  const double t2 = (2.0 / J) * (dw.dI1 * s.minor * s.minor + J * J * dw.dI2);
  return {std::max(t1, t2), std::min(t1, t2)};
}

} // namespace capsula::elasticity
