#include "capsula/suspension/SuspensionDeck.hpp"

#include "capsula/suspension/RandomPlacement.hpp"
#include "capsula/suspension/SlabVolumes.hpp"
#include "capsula/suspension/SuspensionParameters.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/domain/DomainParameters.hpp>
#include <capsula/mesh/CellSurfaceParameters.hpp>
#include <capsula/scene/SceneParameters.hpp>

#include <Teuchos_Array.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace capsula::suspension {

namespace {

Teuchos::Array<double> triple(double a, double b, double c)
{
  return Teuchos::Array<double>(std::vector<double>{a, b, c});
}

// The body-frame surface of a type: its keys with the cell at the origin, unrotated.
mesh::SurfaceMesh bodyShape(const SuspensionType& type)
{
  Teuchos::ParameterList cell = type.cell;
  cell.set("Center", triple(0.0, 0.0, 0.0));
  cell.set("Orientation axis", triple(0.0, 0.0, 1.0));
  cell.set("Orientation angle", 0.0);
  return mesh::buildCellSurface(cell, "Suspension/Cell types/" + type.name);
}

// The flat-faceted volume, the one the hematocrit profile measures (HematocritProfile.hpp).
double facetedVolume(const mesh::SurfaceMesh& shape)
{
  return volumeBelow(shape, std::numeric_limits<double>::max());
}

} // namespace

PlacedSuspension placeSuspension(const Teuchos::ParameterList& deck)
{
  const auto& cells = deck.sublist("Cells");
  for (auto it = cells.begin(); it != cells.end(); ++it) {
    core::require<core::InputError>(!cells.isSublist(cells.name(it)), "'Cells/", cells.name(it),
                                    "' is given, but the cells of a suspension are placed from "
                                    "'Suspension/Cell types': leave 'Cells' to the placement (its 'Minimum gap' "
                                    "stays yours).");
  }
  const SuspensionSettings settings = readSuspensionSettings(deck.sublist("Suspension"));
  const domain::Domain domain = domain::readDomain(deck);
  core::require<core::InputError>(domain.hasUpperWall() && domain.isPeriodic(domain::flowAxis) &&
                                      domain.isPeriodic(domain::vorticityAxis),
                                  "A suspension fills a channel periodic along x and z: set 'Wall/Channel height', "
                                  "'Domain/Periodic length x' and 'Domain/Periodic length z' (now ",
                                  domain.describe(), ").");
  const double box = domain.period(domain::flowAxis) * domain.channelHeight() * domain.period(domain::vorticityAxis);

  PlacedSuspension out;
  std::vector<CellType> types;
  double volume = 0.0;
  for (const SuspensionType& type : settings.types) {
    CellType placed{type.name, bodyShape(type), type.count};
    const double cellVolume = facetedVolume(placed.shape);
    if (type.count == 0) {
      placed.count = cellsForHematocrit(settings.hematocrit, cellVolume, domain);
      out.hematocrit = placed.count * cellVolume / box;
      out.fillingType = type.name;
    }
    volume += placed.count * cellVolume;
    out.types.push_back(type.name);
    out.counts.push_back(placed.count);
    types.push_back(std::move(placed));
  }
  out.volumeFraction = volume / box;

  PlacementSettings placement;
  placement.seed = settings.seed;
  placement.attempts = settings.attempts;
  placement.minimumCellGap = cells.get<double>("Minimum gap");
  placement.minimumWallGap = deck.sublist("Wall").get<double>("Minimum gap");
  const std::vector<PlacedCell> placed = placeCells(types, domain, placement);

  // 'Cells' goes last, after 'Suspension': a restart whose deck places other cells (another
  // seed, say) is refused naming the 'Suspension' key that differs, not the first cell's centre.
  out.deck = deck;
  Teuchos::ParameterList scene = deck.sublist("Cells");
  out.deck.remove("Cells");
  for (std::size_t c = 0; c < placed.size(); ++c) {
    const SuspensionType& type = settings.types[static_cast<std::size_t>(placed[c].type)];
    Teuchos::ParameterList cell = type.cell;
    cell.set("Type", type.name);
    cell.set("Center", triple(placed[c].centre[0], placed[c].centre[1], placed[c].centre[2]));
    cell.set("Orientation axis", triple(placed[c].axis[0], placed[c].axis[1], placed[c].axis[2]));
    cell.set("Orientation angle", placed[c].angleDegrees);
    scene.set(scene::cellSublistName(static_cast<int>(c)), cell);
  }
  out.deck.set("Cells", scene);
  return out;
}

std::string describePlacement(const PlacedSuspension& placed)
{
  std::ostringstream line;
  int total = 0;
  for (std::size_t t = 0; t < placed.types.size(); ++t) {
    line << (t ? ", " : "") << placed.counts[t] << " " << placed.types[t];
    total += placed.counts[t];
  }
  line << " (" << total << " cells, volume fraction " << placed.volumeFraction;
  if (placed.hematocrit > 0.0) {
    line << ", hematocrit " << placed.hematocrit;
  }
  line << ")";
  return line.str();
}

} // namespace capsula::suspension
