#pragma once
// A suspension deck turned into the scene deck that every 3D app runs: the cells of the
// 'Suspension' sublist (SuspensionParameters.hpp) placed at random in the periodic channel
// (placeCells, RandomPlacement.hpp) and written as 'Cells/Cell 0', 'Cell 1', ...: each the
// keys of its type, with the placement's 'Center', 'Orientation axis' and 'Orientation angle'
// (degrees) and its type's name as 'Type'. The cells are in the placement's order: the largest
// types first, each type's cells together. The placement is seeded, so the same deck gives
// the same scene deck on every machine and at every restart.
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace capsula::suspension {

struct PlacedSuspension {
  Teuchos::ParameterList deck;    ///< the deck with 'Cells/Cell k' (not yet validated)
  std::vector<std::string> types; ///< the types, in the deck's order
  std::vector<int> counts;        ///< cells of each type
  std::string fillingType;        ///< the type whose Count is 0 (empty without one)
  double hematocrit = 0.0;        ///< the filling type's volume fraction reached (0 without one)
  double volumeFraction = 0.0;    ///< all cells' volume over the channel's
};

/// Places the cells of the validated deck `deck`. Throws core::InputError, naming the key,
/// for a deck that gives 'Cells/Cell k' itself, for a domain that is not a channel periodic
/// along x and z, for a hematocrit that no whole number of cells meets within 1%, and for a
/// packing that jams (RandomPlacement.hpp).
PlacedSuspension placeSuspension(const Teuchos::ParameterList& deck);

/// One line per type for the run's log: count, volume fraction, shape.
std::string describePlacement(const PlacedSuspension& placed);

} // namespace capsula::suspension
