#pragma once
// The deck's 'Suspension' sublist (the suspension3d app, docs/suspension3d.md), declared and
// read here:
//
//   Suspension/Hematocrit            the volume fraction of the cell type whose Count is 0
//   Suspension/Seed                  the placement's random sequence (RandomPlacement.hpp)
//   Suspension/Attempts              tries per cell before the packing counts as jammed
//   Suspension/Cell types/<name>/    one sublist per type: Count (0: as many as the
//                                    hematocrit asks) and the keys of a cell
//                                    (scene::declareCellParameters) but the three the
//                                    placement sets: Center, Orientation axis, Orientation angle
//
// The valid list depends on the deck: one 'Cell types/<name>' for every type the deck names
// (one type 'cell' when it names none, as --print-defaults shows it). A type's name becomes
// each of its cells' 'Type' and the suffix of its columns, so it is a word: a letter, then
// letters, digits or underscores.
#include <capsula/elasticity/MembraneLawRegistry.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace capsula::suspension {

/// Declares the 'Suspension' sublist in `valid` with a 'Cell types/<name>' for every type
/// of `deck` (the raw deck); each type's 'Membrane law' chooses among `laws`. Throws
/// core::InputError naming the sublist for a type name that is not a word.
void declareSuspensionParameters(Teuchos::ParameterList& valid, const Teuchos::ParameterList& deck,
                                 const elasticity::MembraneLawRegistry& laws = elasticity::builtInMembraneLaws());

struct SuspensionType {
  std::string name;
  int count = 0;               ///< 'Count'; 0: the type that fills the hematocrit
  Teuchos::ParameterList cell; ///< the type's cell keys (Count left out)
};

struct SuspensionSettings {
  double hematocrit = 0.0;           ///< 'Hematocrit'
  bool hematocritGiven = false;      ///< whether the deck gives 'Hematocrit' (not its default)
  unsigned long long seed = 1;       ///< 'Seed'
  int attempts = 0;                  ///< 'Attempts'
  std::vector<SuspensionType> types; ///< in the deck's order
};

/// Reads the 'Suspension' sublist of a validated deck. Throws core::InputError, naming the
/// keys, when more than one type leaves 'Count' at 0 (which of them fills the hematocrit is
/// not said), when none does while the deck gives 'Suspension/Hematocrit' (a key without
/// effect), or when the types add up to no cell.
SuspensionSettings readSuspensionSettings(const Teuchos::ParameterList& suspension);

} // namespace capsula::suspension
