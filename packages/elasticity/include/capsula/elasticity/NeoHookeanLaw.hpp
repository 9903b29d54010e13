#pragma once
// Neo-Hookean membrane (thesis eq 3.31, thin-sheet limit of an incompressible
// neo-Hookean solid; Barthes-Biesel, Diaz & Dhenin 2002):
//     w = G/2 (lambda1^2 + lambda2^2 + 1/(lambda1^2 lambda2^2) - 3)
//       = G/2 (I1 + 1/(I2 + 1) - 1).
// The printed eq 3.31 omits the constant -3, which only shifts w so that it vanishes
// at rest; the tensions are the same.
#include "capsula/elasticity/MembraneLaw.hpp"

namespace capsula::elasticity {

inline double neoHookeanEnergyDensity(double shearModulus, double I1, double I2)
{
  return 0.5 * shearModulus * (I1 + 1.0 / (I2 + 1.0) - 1.0);
}

inline EnergyDerivatives neoHookeanEnergyDerivatives(double shearModulus, double /*I1*/, double I2)
{
  const double areaRatioSquared = I2 + 1.0; // (lambda1 lambda2)^2
  return {0.5 * shearModulus, -0.5 * shearModulus / (areaRatioSquared * areaRatioSquared)};
}

inline EnergySecondDerivatives neoHookeanEnergySecondDerivatives(double shearModulus, double /*I1*/, double I2)
{
  const double areaRatioSquared = I2 + 1.0;
  return {0.0, 0.0, shearModulus / (areaRatioSquared * areaRatioSquared * areaRatioSquared)};
}

class NeoHookeanLaw final : public MembraneLaw {
public:
  /// The deck name (MembraneLawRegistry.hpp).
  static constexpr const char* registeredName = "NeoHookean";

  /// Throws InputError unless G is finite and positive.
  explicit NeoHookeanLaw(double shearModulus) : shearModulus_(shearModulus)
  {
    requireModulus(registeredName, "shear modulus G", shearModulus);
  }

  std::string name() const override { return registeredName; }
  double shearModulus() const override { return shearModulus_; }
  double energyDensity(double I1, double I2) const override { return neoHookeanEnergyDensity(shearModulus_, I1, I2); }
  EnergyDerivatives energyDerivatives(double I1, double I2) const override
  {
    return neoHookeanEnergyDerivatives(shearModulus_, I1, I2);
  }
  EnergySecondDerivatives energySecondDerivatives(double I1, double I2) const override
  {
    return neoHookeanEnergySecondDerivatives(shearModulus_, I1, I2);
  }

private:
  double shearModulus_;
};

} // namespace capsula::elasticity
