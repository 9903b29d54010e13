#pragma once
// A membrane law registered from outside the elasticity package, the example of
// docs/extending.md: the generalised Hooke law of a thin sheet (Barthes-Biesel, Diaz &
// Dhenin 2002), linear in the Green strain,
//     w = G / (4 (1 - nu)) (I1^2 + 2 (1 - nu) (I1 - I2)),
// with its one key 'Poisson ratio' nu (-1 < nu < 1). Small deformations: shear modulus G
// (dw/dI1 = -dw/dI2 = G/2 at rest) and area-dilation modulus G (1 + nu) / (1 - nu).
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/elasticity/MembraneLawRegistry.hpp>

#include <memory>
#include <string>

namespace capsula::scene::testing {

class HookeanMembraneLaw final : public elasticity::MembraneLaw {
public:
  static constexpr const char* registeredName = "Hookean";
  static constexpr const char* poissonRatioKey = "Poisson ratio";

  HookeanMembraneLaw(double shearModulus, double poissonRatio)
      : shearModulus_(shearModulus), poissonRatio_(poissonRatio)
  {
    elasticity::requireModulus(registeredName, "shear modulus G", shearModulus);
  }

  std::string name() const override { return registeredName; }
  double shearModulus() const override { return shearModulus_; }
  double energyDensity(double I1, double I2) const override
  {
    return scale() * (I1 * I1 + 2.0 * (1.0 - poissonRatio_) * (I1 - I2));
  }
  elasticity::EnergyDerivatives energyDerivatives(double I1, double /*I2*/) const override
  {
    return {scale() * (2.0 * I1 + 2.0 * (1.0 - poissonRatio_)), -2.0 * scale() * (1.0 - poissonRatio_)};
  }
  elasticity::EnergySecondDerivatives energySecondDerivatives(double /*I1*/, double /*I2*/) const override
  {
    return {2.0 * scale(), 0.0, 0.0};
  }

private:
  double scale() const { return shearModulus_ / (4.0 * (1.0 - poissonRatio_)); }

  double shearModulus_;
  double poissonRatio_;
};

/// Adds "Hookean" with its key to `laws`.
inline void registerHookeanMembraneLaw(elasticity::MembraneLawRegistry& laws)
{
  auto keys = Teuchos::rcp(new Teuchos::ParameterList(HookeanMembraneLaw::registeredName));
  core::declareReal(*keys, HookeanMembraneLaw::poissonRatioKey, 0.5,
                    "Hookean law: the membrane's two-dimensional Poisson ratio nu_s.", core::greaterThan(-1.0),
                    core::lessThan(1.0));
  laws.add(HookeanMembraneLaw::registeredName,
           {"generalised Hooke law, linear in the Green strain (Barthes-Biesel et al. 2002).", keys},
           [](double shearModulus, const Teuchos::ParameterList& settings) {
             return std::make_unique<HookeanMembraneLaw>(shearModulus,
                                                         settings.get<double>(HookeanMembraneLaw::poissonRatioKey));
           });
}

} // namespace capsula::scene::testing
