#pragma once
// Deck name -> MembraneLaw2D of the 2D cell's contour ('Cell/Membrane law' of tether2d).
//
// A law is a class deriving from MembraneLaw2D registered with a factory from the elastic
// modulus (E = 1: the 2D capillary number is defined with it) and the law's own keys, as
// in 3D (MembraneLawRegistry.hpp). "Hookean" (eq A.36) is built in.
#include "capsula/scene2d/MembraneLaw2D.hpp"

#include <capsula/elasticity/MembraneLawCatalogue.hpp>

namespace capsula::scene2d {

using MembraneLawRegistry2D = elasticity::MembraneLawCatalogue<MembraneLaw2D>;

/// Registers "Hookean" (gamma = E (omega - 1), eq A.36).
void registerBuiltInMembraneLaws2D(MembraneLawRegistry2D& registry);

/// A registry holding the built-in 2D laws.
MembraneLawRegistry2D builtInMembraneLaws2D();

} // namespace capsula::scene2d
