#pragma once
// Constitutive law of a thin hyperelastic membrane (thesis Section 3.5.1).
//
// A law is its strain energy per unit REFERENCE area, w(I1, I2), written in the
// invariants of the left Cauchy-Green tensor B = A A^T (eq 3.29):
//     I1 = lambda1^2 + lambda2^2 - 2,     I2 = lambda1^2 lambda2^2 - 1,
// which both vanish in the unstressed state. The Cauchy tension (eq 3.30) needs only
// the two first derivatives; the tangent stiffness of the stiff time integrators
// (MembraneEnergyHessian.hpp) the second ones. Adding a law means one small class
// deriving from MembraneLaw (see NeoHookeanLaw.hpp) registered by name with its own keys
// (MembraneLawRegistry.hpp, docs/extending.md).
#include <string>

namespace capsula::elasticity {

/// dw/dI1 and dw/dI2 at one state.
struct EnergyDerivatives {
  double dI1;
  double dI2;
};

/// The second derivatives of w at one state.
struct EnergySecondDerivatives {
  double dI1dI1;
  double dI1dI2;
  double dI2dI2;
};

class MembraneLaw {
public:
  virtual ~MembraneLaw() = default;

  /// The name the registry knows the law by ("NeoHookean", "Skalak").
  virtual std::string name() const = 0;
  /// G, the small-deformation surface shear modulus: the natural scale of tensions.
  virtual double shearModulus() const = 0;
  /// w(I1, I2), strain energy per unit reference area; zero at I1 = I2 = 0.
  virtual double energyDensity(double I1, double I2) const = 0;
  /// (dw/dI1, dw/dI2).
  virtual EnergyDerivatives energyDerivatives(double I1, double I2) const = 0;
  /// (d2w/dI1^2, d2w/dI1dI2, d2w/dI2^2).
  virtual EnergySecondDerivatives energySecondDerivatives(double I1, double I2) const = 0;
};

/// Throws core::InputError naming the law, the modulus and its value unless the
/// modulus is finite and positive (or, with allowZero, non-negative).
void requireModulus(const char* law, const char* modulus, double value, bool allowZero = false);

} // namespace capsula::elasticity
