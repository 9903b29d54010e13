#include "capsula/elasticity/MembraneLawRegistry2D.hpp"

#include "capsula/elasticity/HookeanLaw2D.hpp"

namespace capsula::elasticity {

void registerBuiltInMembraneLaws2D(MembraneLawRegistry2D& registry)
{
  registry.add(HookeanLaw2D::registeredName,
               {"tension proportional to the strain, gamma = E (omega - 1) (eq A.36).", Teuchos::null},
               [](double modulus, const Teuchos::ParameterList& /*settings*/) {
                 return std::make_unique<HookeanLaw2D>(modulus);
               });
}

MembraneLawRegistry2D builtInMembraneLaws2D()
{
  MembraneLawRegistry2D registry;
  registerBuiltInMembraneLaws2D(registry);
  return registry;
}

} // namespace capsula::elasticity
