#include "capsula/suspension/SuspensionParameters.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/scene/SceneParameters.hpp>

namespace capsula::suspension {

namespace {

// The keys of a cell that the placement sets for each cell (RandomPlacement.hpp).
constexpr const char* kPlacedKeys[] = {"Center", "Orientation axis", "Orientation angle"};

std::vector<std::string> typeNamesOf(const Teuchos::ParameterList& deck)
{
  std::vector<std::string> names;
  if (deck.isSublist("Suspension") && deck.sublist("Suspension").isSublist("Cell types")) {
    const auto& types = deck.sublist("Suspension").sublist("Cell types");
    for (auto it = types.begin(); it != types.end(); ++it) {
      if (types.isSublist(types.name(it))) {
        names.push_back(types.name(it));
      }
    }
  }
  return names;
}

} // namespace

void declareSuspensionParameters(Teuchos::ParameterList& valid, const Teuchos::ParameterList& deck,
                                 const elasticity::MembraneLawRegistry& laws)
{
  auto& suspension =
      core::declareSublist(valid, "Suspension",
                           "The cells of a suspension, placed at random in the periodic channel at the start of a run "
                           "(packages/suspension RandomPlacement.hpp, docs/suspension3d.md).");
  core::declareReal(suspension, "Hematocrit", 0.2,
                    "The volume fraction of the cell type whose 'Count' is 0 (the red cells) in the "
                    "channel L_x H L_z, from the flat-faceted volume of one cell (docs/suspensions.md). "
                    "Refused when the nearest whole number of cells misses it by more than 1%.",
                    core::greaterThan(0.0), core::lessThan(1.0));
  core::declareInt(suspension, "Seed", 1,
                   "The placement's random sequence: the same seed, types and box place the same cells "
                   "on every machine.",
                   0);
  core::declareInt(suspension, "Attempts", 20000,
                   "Random positions tried per cell before the packing counts as jammed (an input "
                   "error saying how far it got).",
                   1);
  auto& types =
      core::declareSublist(suspension, "Cell types",
                           "One sublist per cell type, named by a word (red_cell, platelet): its 'Count' and the keys "
                           "of a cell but Center and Orientation, which the placement sets.");
  std::vector<std::string> names = typeNamesOf(deck);
  if (names.empty()) {
    names.push_back("cell");
  }
  for (const auto& name : names) {
    core::require<core::InputError>(scene::isCellTypeName(name), "'Suspension/Cell types/", name,
                                    "': a type's name must be a word (a letter, then letters, digits or "
                                    "underscores), since its cells' columns are named after it.");
    auto& type = core::declareSublist(types, name, "A cell type.");
    core::declareInt(type, "Count", 0,
                     "How many cells of this type. 0: as many as 'Suspension/Hematocrit' asks (one type "
                     "at most).",
                     0);
    scene::declareCellParameters(type, {0.0, 0.0, 0.0}, laws);
    for (const char* key : kPlacedKeys) {
      type.remove(key);
    }
    type.remove("Type"); // the type's name
  }
}

SuspensionSettings readSuspensionSettings(const Teuchos::ParameterList& suspension)
{
  SuspensionSettings out;
  out.hematocrit = suspension.get<double>("Hematocrit");
  out.hematocritGiven = !suspension.getEntry("Hematocrit").isDefault();
  out.seed = static_cast<unsigned long long>(suspension.get<int>("Seed"));
  out.attempts = suspension.get<int>("Attempts");
  const auto& types = suspension.sublist("Cell types");
  std::string filling;
  int counted = 0;
  for (auto it = types.begin(); it != types.end(); ++it) {
    if (!types.isSublist(types.name(it))) {
      continue;
    }
    SuspensionType type;
    type.name = types.name(it);
    type.cell = types.sublist(type.name);
    type.count = type.cell.get<int>("Count");
    type.cell.remove("Count");
    if (type.count == 0) {
      core::require<core::InputError>(filling.empty(), "'Suspension/Cell types/", filling, "/Count' and '", type.name,
                                      "/Count' are both 0: only one type can fill 'Suspension/Hematocrit'; "
                                      "give the other a count.");
      filling = type.name;
    }
    counted += type.count;
    out.types.push_back(std::move(type));
  }
  core::require<core::InputError>(!filling.empty() || !out.hematocritGiven,
                                  "'Suspension/Hematocrit' is given, but every type of 'Suspension/Cell types' has "
                                  "a 'Count': the hematocrit would have no effect. Set one type's 'Count' to 0 "
                                  "or leave the hematocrit out.");
  core::require<core::InputError>(!filling.empty() || counted > 0,
                                  "'Suspension/Cell types' places no cell: give a type a 'Count'.");
  return out;
}

} // namespace capsula::suspension
