#pragma once
// The parameters of the Helfrich bending energy (k_b / 2) int_S (2H - c)^2 dA
// (HelfrichBending.hpp), as a deck gives them.
#include <string>

namespace capsula::elasticity {

/// What shape the bending energy leaves stress-free.
enum class BendingReference {
  Flat,        ///< c = c0 everywhere: with c0 = 0 only a flat sheet is unbent
  InitialShape ///< c_k = 2 H_k of the reference shape at every node (c0 must be 0)
};

/// "Flat" / "Initial shape" (the deck's names) and back; throws core::InputError naming
/// the key `Bending reference` for an unknown name.
BendingReference bendingReference(const std::string& name);
std::string to_string(BendingReference reference);

struct BendingParameters {
  double modulus = 0.0;                                ///< k_b >= 0 (deck key `Bending modulus`)
  double spontaneousCurvature = 0.0;                   ///< c0, a constant (deck key `Spontaneous curvature`)
  BendingReference reference = BendingReference::Flat; ///< deck key `Bending reference`
};

} // namespace capsula::elasticity
