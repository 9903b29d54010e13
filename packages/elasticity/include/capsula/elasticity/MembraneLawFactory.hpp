#pragma once
// Membrane laws by name, for decks: makeMembraneLaw("Skalak", {G, C}).
#include "capsula/elasticity/MembraneLaw.hpp"

#include <memory>
#include <string>
#include <vector>

namespace capsula::elasticity {

struct MembraneLawParameters {
  double shearModulus = 1.0; ///< G
  double areaDilation = 0.0; ///< C (Skalak only; ignored by NeoHookean)
};

/// The names makeMembraneLaw accepts.
std::vector<std::string> membraneLawNames();

/// Throws InputError for an unknown name (listing the known ones) or invalid moduli.
std::unique_ptr<MembraneLaw> makeMembraneLaw(const std::string& name, const MembraneLawParameters& parameters);

} // namespace capsula::elasticity
