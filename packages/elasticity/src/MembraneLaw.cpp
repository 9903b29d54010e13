#include "capsula/elasticity/MembraneLaw.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>

namespace capsula::elasticity {

void requireModulus(const char* law, const char* modulus, double value, bool allowZero)
{
  const bool valid = std::isfinite(value) && (allowZero ? value >= 0.0 : value > 0.0);
  core::require<core::InputError>(valid, "the ", law, " membrane law needs a ", allowZero ? "non-negative" : "positive",
                                  " finite ", modulus, ", got ", value, "; give ", modulus,
                                  allowZero ? " >= 0" : " > 0");
}

} // namespace capsula::elasticity
