#include "capsula/scene2d/HookeanLaw2D.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>

namespace capsula::scene2d {

HookeanLaw2D::HookeanLaw2D(double modulus) : modulus_(modulus)
{
  core::require<core::InputError>(std::isfinite(modulus) && modulus > 0.0,
                                  "the 2D Hookean membrane needs a positive elastic modulus E, got ", modulus,
                                  "; give E > 0");
}

} // namespace capsula::scene2d
