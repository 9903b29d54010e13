#include "capsula/elasticity/BendingParameters.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::elasticity {

BendingReference bendingReference(const std::string& name)
{
  if (name == "Flat") {
    return BendingReference::Flat;
  }
  core::require<core::InputError>(name == "Initial shape", "unknown Bending reference '", name,
                                  "': use 'Flat' or 'Initial shape'");
  return BendingReference::InitialShape;
}

std::string to_string(BendingReference reference)
{
  return reference == BendingReference::Flat ? "Flat" : "Initial shape";
}

} // namespace capsula::elasticity
