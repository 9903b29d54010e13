#include "capsula/scene/SceneDescription.hpp"

#include "capsula/scene/SceneParameters.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::scene {

namespace core = capsula::core;

bool SceneDescription::anyFixedHeight() const
{
  for (const auto& cell : cells) {
    if (cell.fixedHeight) {
      return true;
    }
  }
  return false;
}

namespace {

int countCells(const Teuchos::ParameterList& cells)
{
  int count = 0;
  for (auto it = cells.begin(); it != cells.end(); ++it) {
    if (cells.isSublist(cells.name(it))) {
      ++count;
    }
  }
  return count;
}

} // namespace

SceneDescription describeScene(const Teuchos::ParameterList& deck)
{
  SceneDescription scene;
  const auto& flow = deck.sublist("Flow");
  scene.capillaryNumber = flow.get<double>("Capillary number");
  scene.viscosityRatio = flow.get<double>("Viscosity ratio");
  if (flow.isSublist("Shear rate")) {
    scene.shearRate = operators::readShearRate(flow.sublist("Shear rate"), "Flow/Shear rate");
  }
  scene.wall = deck.sublist("Wall").get<bool>("Enabled");
  scene.minimumWallGap = deck.sublist("Wall").get<double>("Minimum gap");

  const auto& cells = deck.sublist("Cells");
  scene.minimumGap = cells.get<double>("Minimum gap");
  const int n = countCells(cells);
  core::require<core::InputError>(n >= 1, "'Cells' has no cell: add a sublist 'Cells/Cell 0'.");
  for (int c = 0; c < n; ++c) {
    const std::string name = cellSublistName(c);
    core::require<core::InputError>(cells.isSublist(name), "'Cells' holds ", n, " cell sublists but no '", name,
                                    "': number the cells 'Cell 0' to 'Cell ", n - 1, "' without gaps.");
    const auto& list = cells.sublist(name);
    CellDescription cell;
    cell.path = "Cells/" + name;
    cell.surface = list;
    cell.membraneLaw = list.get<std::string>("Membrane law");
    cell.membraneForces = list.get<std::string>("Membrane forces");
    cell.shearModulus = list.get<double>("Shear modulus");
    cell.areaDilation = list.get<double>("Area dilation C");
    cell.prestress = list.get<double>("Prestress");
    cell.fixedHeight = list.get<bool>("Fixed height");
    cell.meshLevel = list.get<int>("Mesh level");
    core::require<core::InputError>(!cell.fixedHeight || scene.wall, "'", cell.path,
                                    "/Fixed height' is true but 'Wall/Enabled' is false: a fixed "
                                    "height above the wall needs the wall.");
    scene.cells.push_back(std::move(cell));
  }

  scene.meshRegularisation = mesh::readRedistributionParameters(deck.sublist("Mesh regularisation"));
  scene.meshAdaption = mesh::readAdaptionParameters(deck.sublist("Mesh adaption"));
  return scene;
}

} // namespace capsula::scene
