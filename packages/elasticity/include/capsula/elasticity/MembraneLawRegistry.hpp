#pragma once
// Deck name -> MembraneLaw of a 3D cell surface ('Cells/Cell k/Membrane law').
//
// A law is a class deriving from MembraneLaw (NeoHookeanLaw.hpp) registered with a factory
// from the cell's shear modulus and the law's own keys; the registry declares those keys
// in every cell's sublist (MembraneLawChoice.hpp), so a new law touches no list of names.
// "NeoHookean" and "Skalak" are built in.
#include "capsula/elasticity/MembraneLaw.hpp"
#include "capsula/elasticity/MembraneLawCatalogue.hpp"

namespace capsula::elasticity {

using MembraneLawRegistry = MembraneLawCatalogue<MembraneLaw>;

/// Registers "NeoHookean" (eq 3.31) and "Skalak" (eq 3.32, with its key 'Area dilation C').
void registerBuiltInMembraneLaws(MembraneLawRegistry& registry);

/// A registry holding the built-in laws.
MembraneLawRegistry builtInMembraneLaws();

} // namespace capsula::elasticity
