#include "capsula/elasticity/MembraneLawFactory.hpp"

#include "capsula/elasticity/NeoHookeanLaw.hpp"
#include "capsula/elasticity/SkalakLaw.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::elasticity {

std::vector<std::string> membraneLawNames()
{
  return {"NeoHookean", "Skalak"};
}

std::unique_ptr<MembraneLaw> makeMembraneLaw(const std::string& name, const MembraneLawParameters& parameters)
{
  if (name == "NeoHookean") {
    return std::make_unique<NeoHookeanLaw>(parameters.shearModulus);
  }
  if (name == "Skalak") {
    return std::make_unique<SkalakLaw>(parameters.shearModulus, parameters.areaDilation);
  }
  std::string known;
  for (const std::string& law : membraneLawNames()) {
    known += (known.empty() ? "" : ", ") + law;
  }
  throw core::InputError(core::message("unknown membrane law '", name, "'; choose one of: ", known));
}

} // namespace capsula::elasticity
