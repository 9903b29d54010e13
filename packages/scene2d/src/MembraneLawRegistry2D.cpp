#include "capsula/scene2d/MembraneLawRegistry2D.hpp"

#include "capsula/scene2d/HookeanLaw2D.hpp"

namespace capsula::scene2d {

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

} // namespace capsula::scene2d
