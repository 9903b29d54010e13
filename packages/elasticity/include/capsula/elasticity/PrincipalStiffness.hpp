#pragma once
// The in-plane stiffness of a hyperelastic membrane along its principal directions,
//     k_i = d2w / d lambda_i^2   (the other stretch held),
// the slope of the nominal principal tension P_i = dw / d lambda_i = lambda_j T_i against its
// own stretch. With w(I1, I2), I1 = lambda1^2 + lambda2^2 - 2 and I2 = lambda1^2 lambda2^2 - 1,
//     k_1 = 2 w_1 + 2 lambda2^2 w_2 + 4 lambda1^2 (w_11 + 2 lambda2^2 w_12 + lambda2^4 w_22)
// (w_1 = dw/dI1, w_12 = d2w/dI1dI2, ...), and k_2 the same with the stretches swapped.
//
// Where k_i < 0 the law softens as the membrane is compressed (or stretched) further along i:
// the more a strip of material is squeezed, the less tension it takes to squeeze it more, so
// material crowds into an ever narrower strip. Bending does not resist it (the surface need not
// change shape), so nothing in the model sets its width and it narrows to the element size.
// The Skalak law (eq 3.32) has such a limit in compression for every C: at lambda2 = 1,
//     k_1 = G (1 + C) (3 lambda1^2 - 1) < 0   for lambda1 < 1/sqrt(3) = 0.577,
// and in general below lambda1^2 = (1 + C lambda2^2) / (3 (1 + C lambda2^4)); a large C keeps a
// cell away from it by holding its area (lambda1 lambda2 ~ 1). The neo-Hookean law (eq 3.31)
// has none: k_1 = G (1 + 3 / (lambda1^4 lambda2^2)) > 0. Inline and allocation-free.
#include "capsula/elasticity/MembraneLaw.hpp"
#include "capsula/elasticity/SurfaceKinematics.hpp"

#include <algorithm>

namespace capsula::elasticity {

/// k along the stretch `along` with `other` held (formula above), from the law's derivatives
/// at the state's invariants.
inline double principalStiffness(double along, double other, const EnergyDerivatives& dw,
                                 const EnergySecondDerivatives& d2w)
{
  const double a2 = along * along;
  const double o2 = other * other;
  return 2.0 * dw.dI1 + 2.0 * o2 * dw.dI2 + 4.0 * a2 * (d2w.dI1dI1 + 2.0 * o2 * d2w.dI1dI2 + o2 * o2 * d2w.dI2dI2);
}

/// The smaller of the two principal stiffnesses of `law` at the principal stretches `s`.
inline double leastPrincipalStiffness(const MembraneLaw& law, const PrincipalStretches& s)
{
  const StrainInvariants I = strainInvariants(s);
  const EnergyDerivatives dw = law.energyDerivatives(I.I1, I.I2);
  const EnergySecondDerivatives d2w = law.energySecondDerivatives(I.I1, I.I2);
  return std::min(principalStiffness(s.major, s.minor, dw, d2w), principalStiffness(s.minor, s.major, dw, d2w));
}

} // namespace capsula::elasticity
