#include "capsula/elasticity/MembraneLawRegistry.hpp"

#include "capsula/elasticity/NeoHookeanLaw.hpp"
#include "capsula/elasticity/SkalakLaw.hpp"

#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::elasticity {

namespace {

const char* const areaDilationKey = "Area dilation C";

Teuchos::RCP<const Teuchos::ParameterList> validSkalakParameters()
{
  auto keys = Teuchos::rcp(new Teuchos::ParameterList(SkalakLaw::registeredName));
  core::declareReal(*keys, areaDilationKey, 2.5,
                    "Skalak law: area-dilation modulus over shear modulus (C G is the dilation "
                    "modulus). The thesis's Chapter 5 spans 0.5 to 2.5. Read only when 'Membrane law' is Skalak.",
                    core::greaterThan(0.0));
  return keys;
}

} // namespace

void registerBuiltInMembraneLaws(MembraneLawRegistry& registry)
{
  registry.add(NeoHookeanLaw::registeredName, {"thin incompressible neo-Hookean sheet (eq 3.31).", Teuchos::null},
               [](double shearModulus, const Teuchos::ParameterList& /*settings*/) {
                 return std::make_unique<NeoHookeanLaw>(shearModulus);
               });
  registry.add(
      SkalakLaw::registeredName,
      {"red-cell law of Skalak et al. 1973 (eq 3.32), area dilation resisted by C G.", validSkalakParameters()},
      [](double shearModulus, const Teuchos::ParameterList& settings) {
        return std::make_unique<SkalakLaw>(shearModulus, settings.get<double>(areaDilationKey));
      });
}

MembraneLawRegistry builtInMembraneLaws()
{
  MembraneLawRegistry registry;
  registerBuiltInMembraneLaws(registry);
  return registry;
}

} // namespace capsula::elasticity
