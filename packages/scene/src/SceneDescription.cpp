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
  scene.wall = deck.sublist("Wall").get<bool>("Enabled");

  const auto& cells = deck.sublist("Cells");
  scene.minimumGap = cells.get<double>("Minimum gap");
  const int n = countCells(cells);
  core::require<core::InputError>(n >= 1, "'Cells' has no cell: add a sublist 'Cells/Cell 0'.");
  for (int c = 0; c < n; ++c) {
    const std::string name = cellSublistName(c);
    core::require<core::InputError>(cells.isSublist(name), "'Cells' holds ", n,
                                    " cell sublists but no '", name,
                                    "': number the cells 'Cell 0' to 'Cell ", n - 1,
                                    "' without gaps.");
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

  const auto& output = deck.sublist("Output");
  OutputDescription& out = scene.output;
  out.directory = output.get<std::string>("Directory");
  out.interval = output.get<double>("Interval");
  out.snapshots = output.get<bool>("Snapshots");
  out.snapshotStride = output.get<int>("Snapshot stride");
  out.checkpoint = output.get<bool>("Checkpoint");
  out.progressSteps = output.get<int>("Progress steps");
  const auto& probes = output.get<Teuchos::Array<double>>("Flow probes");
  core::require<core::InputError>(probes.size() % 3 == 0, "'Output/Flow probes' has ",
                                  probes.size(),
                                  " numbers; give whole points, three coordinates each.");
  for (Teuchos::Array<double>::size_type k = 0; k < probes.size(); k += 3) {
    out.flowProbes.emplace_back(probes[k], probes[k + 1], probes[k + 2]);
    core::require<core::InputError>(!scene.wall || probes[k + 1] > 0.0, "'Output/Flow probes' point ",
                                    k / 3, " lies at y = ", probes[k + 1],
                                    ", not in the fluid above the wall y = 0.");
  }
  out.minimumAngle = output.sublist("Stability").get<double>("Minimum angle");
  scene.meshRegularisation = mesh::readRedistributionParameters(deck.sublist("Mesh regularisation"));
  scene.meshAdaption = mesh::readAdaptionParameters(deck.sublist("Mesh adaption"));
  core::require<core::InputError>(
    !scene.meshRegularisation.enabled || scene.meshRegularisation.triggerAngle > out.minimumAngle,
    "'Mesh regularisation/Minimum angle' = ", scene.meshRegularisation.triggerAngle,
    " must be above 'Output/Stability/Minimum angle' = ", out.minimumAngle,
    ": the run would stop before the nodes are ever redistributed.");
  const auto& wallStress = output.sublist("Wall shear stress");
  WallShearStressOutput& ws = out.wallShearStress;
  ws.enabled = wallStress.get<bool>("Enabled");
  ws.upstream = wallStress.get<double>("Upstream extent");
  ws.downstream = wallStress.get<double>("Downstream extent");
  ws.halfWidth = wallStress.get<double>("Half width");
  ws.spacing = wallStress.get<double>("Spacing");
  ws.threshold = wallStress.get<double>("Threshold");
  const auto& range = wallStress.get<Teuchos::Array<double>>("Isolated range");
  core::require<core::InputError>(range.empty() || (range.size() == 2 && range[0] <= range[1]),
                                  "'Output/Wall shear stress/Isolated range' must be empty or two numbers, "
                                  "the smallest and the largest wall stress of the isolated cell "
                                  "(wall_stress_min, wall_stress_max of its run), smallest first.");
  if (!range.empty()) {
    ws.isolatedRange = true;
    ws.isolatedMinimum = range[0];
    ws.isolatedMaximum = range[1];
  }
  core::require<core::InputError>(!ws.enabled || scene.wall,
                                  "'Output/Wall shear stress/Enabled' is true but 'Wall/Enabled' is "
                                  "false: there is no wall to measure.");
  return scene;
}

} // namespace capsula::scene
