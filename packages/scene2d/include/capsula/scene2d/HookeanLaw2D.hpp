#pragma once
// Hookean law of a 2D membrane (a contour): tension from the local stretch ratio
// (thesis eq A.36, after Breyiannis & Pozrikidis 2000).
#include "capsula/scene2d/MembraneLaw2D.hpp"

namespace capsula::scene2d {

/// gamma = E (omega - 1), omega = dl / dl0 (eqs A.36-A.37).
inline double hookeanTension(double modulus, double stretch)
{
  return modulus * (stretch - 1.0);
}

/// Strain energy per unit reference length, 0.5 E (omega - 1)^2: its derivative in
/// omega is the tension, so int gamma d(omega)/dt dl0 is the rate of stored energy.
inline double hookeanEnergyDensity(double modulus, double stretch)
{
  const double strain = stretch - 1.0;
  return 0.5 * modulus * strain * strain;
}

class HookeanLaw2D final : public MembraneLaw2D {
public:
  /// The deck name (MembraneLawRegistry2D.hpp).
  static constexpr const char* registeredName = "Hookean";

  /// Throws InputError unless the elastic modulus E is positive and finite.
  explicit HookeanLaw2D(double modulus);

  std::string name() const override { return registeredName; }
  double modulus() const { return modulus_; }
  double tension(double stretch) const override { return hookeanTension(modulus_, stretch); }
  double energyDensity(double stretch) const override { return hookeanEnergyDensity(modulus_, stretch); }

private:
  double modulus_;
};

} // namespace capsula::scene2d
