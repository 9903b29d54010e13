#pragma once
// Skalak membrane (Skalak et al. 1973; thesis eq 3.32), the red-cell law:
//     w = G/4 ((lambda1^2 - 1)^2 + (lambda2^2 - 1)^2 + C (lambda1^2 lambda2^2 - 1)^2)
//       = G/4 (I1^2 + 2 I1 - 2 I2 + C I2^2),
// G the shear modulus and C G the area-dilation modulus (C >> 1: nearly
// area-incompressible).
#include "capsula/elasticity/MembraneLaw.hpp"

namespace capsula::elasticity {

inline double skalakEnergyDensity(double shearModulus, double areaDilation, double I1, double I2)
{
  return 0.25 * shearModulus * (I1 * I1 + 2.0 * I1 - 2.0 * I2 + areaDilation * I2 * I2);
}

inline EnergyDerivatives skalakEnergyDerivatives(double shearModulus, double areaDilation, double I1, double I2)
{
  return {0.5 * shearModulus * (I1 + 1.0), 0.5 * shearModulus * (areaDilation * I2 - 1.0)};
}

inline EnergySecondDerivatives skalakEnergySecondDerivatives(double shearModulus, double areaDilation)
{
  return {0.5 * shearModulus, 0.0, 0.5 * shearModulus * areaDilation};
}

class SkalakLaw final : public MembraneLaw {
public:
  /// The deck name (MembraneLawRegistry.hpp).
  static constexpr const char* registeredName = "Skalak";

  /// Throws InputError unless G is finite and positive and C finite and non-negative.
  SkalakLaw(double shearModulus, double areaDilation) : shearModulus_(shearModulus), areaDilation_(areaDilation)
  {
    requireModulus(registeredName, "shear modulus G", shearModulus);
    requireModulus(registeredName, "area-dilation ratio C", areaDilation, true);
  }

  std::string name() const override { return registeredName; }
  double shearModulus() const override { return shearModulus_; }
  double areaDilation() const { return areaDilation_; }
  double energyDensity(double I1, double I2) const override
  {
    return skalakEnergyDensity(shearModulus_, areaDilation_, I1, I2);
  }
  EnergyDerivatives energyDerivatives(double I1, double I2) const override
  {
    return skalakEnergyDerivatives(shearModulus_, areaDilation_, I1, I2);
  }
  EnergySecondDerivatives energySecondDerivatives(double /*I1*/, double /*I2*/) const override
  {
    return skalakEnergySecondDerivatives(shearModulus_, areaDilation_);
  }

private:
  double shearModulus_;
  double areaDilation_;
};

} // namespace capsula::elasticity
