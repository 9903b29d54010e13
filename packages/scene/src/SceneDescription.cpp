#include "capsula/scene/SceneDescription.hpp"

#include "capsula/scene/SceneParameters.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/domain/DomainParameters.hpp>
#include <capsula/elasticity/MembraneLawChoice.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

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

// The bending keys that only make sense together (the validators see one key at a time).
void requireConsistentBending(const CellDescription& cell)
{
  core::require<core::InputError>(std::isfinite(cell.spontaneousCurvature), "'", cell.path,
                                  "/Spontaneous curvature' = ", cell.spontaneousCurvature, " is not a finite number.");
  if (cell.bendingModulus == 0.0) {
    // Keys without effect are refused (docs/user-guide.md, "Keys without effect").
    core::require<core::InputError>(
        cell.spontaneousCurvature == 0.0, "'", cell.path, "/Spontaneous curvature' = ", cell.spontaneousCurvature,
        " has no effect without bending: set '", cell.path, "/Bending modulus' > 0 or the curvature to 0.");
    core::require<core::InputError>(cell.bendingReference == "Flat", "'", cell.path, "/Bending reference' = '",
                                    cell.bendingReference, "' has no effect without bending: set '", cell.path,
                                    "/Bending modulus' > 0 or the reference to 'Flat'.");
    return;
  }
  core::require<core::InputError>(std::isfinite(cell.bendingModulus), "'", cell.path,
                                  "/Bending modulus' is not a finite number.");
  core::require<core::InputError>(cell.membraneForces == "Virtual work", "'", cell.path,
                                  "/Bending modulus' > 0 needs '", cell.path,
                                  "/Membrane forces' = 'Virtual work': bending enters as the nodal forces "
                                  "of its energy, which the contour-integral load has no place for.");
  core::require<core::InputError>(cell.bendingReference == "Flat" || cell.spontaneousCurvature == 0.0, "'", cell.path,
                                  "/Spontaneous curvature' = ", cell.spontaneousCurvature, " and '", cell.path,
                                  "/Bending reference' = 'Initial shape' both set the curvature without "
                                  "moments: keep one of them.");
}

// The ligands in the scene's domain: the plane of 'Adhesion/Ligand wall', and a bounded
// 'Ligand patch' repeated with a periodic box (it must then lie within one box).
void placeLigands(SceneDescription& scene)
{
  adhesion::AdhesionSettings& bonds = scene.adhesion;
  if (!bonds.enabled) {
    return;
  }
  bonds.ligandWall = adhesion::ligandWallPlane(bonds.ligandWallChoice, scene.domain.channelHeight());
  // The anchors are fixed points: the ligand wall must be at rest, which the upper wall of
  // plane Couette flow is not.
  core::require<core::InputError>(
      bonds.ligandWallChoice == adhesion::LigandWallChoice::Lower ||
          scene.flowProfile.kind() == domain::FlowProfileKind::Poiseuille,
      "'Adhesion/Ligand wall' = Upper with 'Flow/Profile' = ", domain::flowProfileName(scene.flowProfile.kind()),
      ": in plane Couette flow the upper wall slides at k H, and the bonds' anchors are fixed points. Put the "
      "ligands on the upper wall in Poiseuille flow ('Flow/Profile' = Poiseuille), where both walls are at rest.");
  adhesion::WallRectangle& patch = bonds.ligandPatch;
  const struct {
    double period, low, high;
    const char* key;
    double* periodOfPatch;
  } axes[] = {{scene.domain.period(domain::flowAxis), patch.xMin, patch.xMax, "x", &patch.periodX},
              {scene.domain.period(domain::vorticityAxis), patch.zMin, patch.zMax, "z", &patch.periodZ}};
  for (const auto& axis : axes) {
    if (axis.period <= 0.0) {
      continue;
    }
    *axis.periodOfPatch = axis.period;
    const bool unbounded = !std::isfinite(axis.low) && !std::isfinite(axis.high);
    core::require<core::InputError>(
        unbounded || (axis.low >= 0.0 && axis.high <= axis.period), "'Adhesion/Ligand patch' spans ", axis.key, " in [",
        axis.low, ", ", axis.high, "], which is not within the periodic box [0, ", axis.period,
        "] of 'Domain/Periodic length ", axis.key, "': the patch repeats with the box, so give it within one box.");
  }
}

// What bonds need of the rest of the scene (the adhesion keys alone are checked by
// readAdhesionParameters).
void requireUsableAdhesion(const SceneDescription& scene)
{
  if (!scene.adhesion.enabled) {
    return;
  }
  core::require<core::InputError>(scene.wall,
                                  "'Adhesion/Enabled' is true but 'Wall/Enabled' is false: the "
                                  "bonds tie the membrane to ligands on the wall y = 0, which needs the wall.");
  // A bond forms only within the reach r_0 and rests at lambda: with lambda > r_0 every new
  // bond pulls the membrane down, and with lambda above the contact range the repulsion holds
  // the membrane where no bond is at rest (no bond formed at t = 0.1 in either case).
  const adhesion::AdhesionSettings& bonds = scene.adhesion;
  core::require<core::InputError>(bonds.equilibriumLength <= bonds.reactionDistance,
                                  "'Adhesion/Equilibrium length' = ", bonds.equilibriumLength,
                                  " is above 'Adhesion/Reaction distance' = ", bonds.reactionDistance,
                                  ": a bond forms only within the reach, and would pull the membrane below it at once. "
                                  "Give a length <= ",
                                  bonds.reactionDistance, " (or a longer reach).");
  core::require<core::InputError>(!scene.contact.enabled || bonds.equilibriumLength <= scene.contact.range,
                                  "'Adhesion/Equilibrium length' = ", bonds.equilibriumLength,
                                  " is above 'Contact/Range' = ", scene.contact.range,
                                  ": the repulsion holds the membrane at a gap where no bond is at rest. Give a length "
                                  "<= ",
                                  scene.contact.range, " (or a wider range).");
  for (const auto& cell : scene.cells) {
    core::require<core::InputError>(cell.membraneForces == "Virtual work", "'Adhesion/Enabled' is true but '",
                                    cell.path,
                                    "/Membrane forces' is 'Contour integral': the bond forces enter "
                                    "as nodal forces, which need 'Virtual work'.");
  }
  // A receptor is a fixed (element, xi, eta) of the mesh: a redistribution or a refinement
  // would move it to another material point under its bond.
  core::require<core::InputError>(!scene.meshRegularisation.enabled,
                                  "'Adhesion/Enabled' and 'Mesh regularisation/Enabled' are both true: the "
                                  "receptors are material points of the mesh, which a redistribution moves. "
                                  "Turn one of them off.");
  core::require<core::InputError>(!scene.meshAdaption.enabled,
                                  "'Adhesion/Enabled' and 'Mesh adaption/Enabled' are both true: the receptors "
                                  "are material points of the mesh, which a refinement renumbers. Turn one of "
                                  "them off.");
}

// What a tether needs of the rest of the scene (its keys alone are checked by
// readTetherParameters).
void requireUsableTether(const SceneDescription& scene)
{
  const adhesion::TetherSettings& tether = scene.tether;
  if (!tether.enabled) {
    return;
  }
  core::require<core::InputError>(scene.wall,
                                  "'Tether/Enabled' is true but 'Wall/Enabled' is false: the tether "
                                  "ties the membrane to an anchor on the wall y = 0, which needs the wall.");
  core::require<core::InputError>(tether.cell < scene.numCells(), "'Tether/Cell' = ", tether.cell,
                                  " but the scene has ", scene.numCells(), " cell(s), 'Cells/Cell 0' to 'Cells/Cell ",
                                  scene.numCells() - 1, "': name one of them.");
  const CellDescription& cell = scene.cells[static_cast<std::size_t>(tether.cell)];
  core::require<core::InputError>(cell.membraneForces == "Virtual work", "'Tether/Enabled' is true but '", cell.path,
                                  "/Membrane forces' is 'Contour integral': the tether's force enters as nodal "
                                  "forces, which need 'Virtual work'.");
  // The tether holds fixed material points (element, xi, eta) of the mesh.
  core::require<core::InputError>(!scene.meshRegularisation.enabled,
                                  "'Tether/Enabled' and 'Mesh regularisation/Enabled' are both true: the tether "
                                  "holds material points of the mesh, which a redistribution moves. Turn one of "
                                  "them off.");
  core::require<core::InputError>(!scene.meshAdaption.enabled,
                                  "'Tether/Enabled' and 'Mesh adaption/Enabled' are both true: the tether holds "
                                  "material points of the mesh, which a refinement renumbers. Turn one of them off.");
}

// The cell's 'Membrane law' with its keys, and the law built from them and the cell's shear
// modulus; a law that refuses its moduli is reported with the cell's path.
void readMembraneLaw(const Teuchos::ParameterList& list, const elasticity::MembraneLawRegistry& laws,
                     CellDescription& cell)
{
  elasticity::MembraneLawChoice choice = elasticity::readMembraneLawChoice(list, laws.infos(), cell.path);
  try {
    cell.law = laws.create(choice.name, cell.shearModulus, choice.parameters);
  } catch (const core::InputError& e) {
    throw core::InputError(core::message("'", cell.path, "': ", e.what()));
  }
  cell.membraneLaw = std::move(choice.name);
  cell.membraneLawParameters = std::move(choice.parameters);
}

} // namespace

std::vector<double> SceneDescription::viscosityRatios() const
{
  std::vector<double> ratios;
  for (const auto& cell : cells) {
    ratios.push_back(cell.viscosityRatio);
  }
  return ratios;
}

bool SceneDescription::allViscosityRatiosOne() const
{
  return std::all_of(cells.begin(), cells.end(),
                     [](const CellDescription& cell) { return cell.viscosityRatio == 1.0; });
}

SceneDescription describeScene(const Teuchos::ParameterList& deck, const elasticity::MembraneLawRegistry& laws)
{
  SceneDescription scene;
  const auto& flow = deck.sublist("Flow");
  scene.capillaryNumber = flow.get<double>("Capillary number");
  scene.viscosityRatio = flow.get<double>("Viscosity ratio");
  if (flow.isSublist("Shear rate")) {
    scene.shearRate = operators::readShearRate(flow.sublist("Shear rate"), "Flow/Shear rate");
  }
  scene.domain = domain::readDomain(deck);
  scene.flowProfile = domain::readFlowProfile(deck, scene.domain);
  scene.wall = scene.domain.hasLowerWall();
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
    cell.type = list.isParameter("Type") ? list.get<std::string>("Type") : std::string();
    core::require<core::InputError>(cell.type.empty() || isCellTypeName(cell.type), "'", cell.path, "/Type' = '",
                                    cell.type,
                                    "': a type is a word (a letter, then letters, digits or underscores), "
                                    "since the outputs name columns after it.");
    cell.membraneForces = list.get<std::string>("Membrane forces");
    cell.shearModulus = list.get<double>("Shear modulus");
    readMembraneLaw(list, laws, cell);
    cell.prestress = list.get<double>("Prestress");
    const double ownRatio = list.isParameter("Viscosity ratio") ? list.get<double>("Viscosity ratio") : 0.0;
    cell.viscosityRatio = ownRatio > 0.0 ? ownRatio : scene.viscosityRatio;
    cell.bendingModulus = list.get<double>("Bending modulus");
    cell.spontaneousCurvature = list.get<double>("Spontaneous curvature");
    cell.bendingReference = list.get<std::string>("Bending reference");
    requireConsistentBending(cell);
    cell.fixedHeight = list.get<bool>("Fixed height");
    cell.conserveVolume = list.get<bool>("Conserve volume");
    cell.meshLevel = list.get<int>("Mesh level");
    core::require<core::InputError>(!cell.fixedHeight || scene.wall, "'", cell.path,
                                    "/Fixed height' is true but 'Wall/Enabled' is false: a fixed "
                                    "height above the wall needs the wall.");
    scene.cells.push_back(std::move(cell));
  }

  scene.meshRegularisation = mesh::readRedistributionParameters(deck.sublist("Mesh regularisation"));
  scene.meshAdaption = mesh::readAdaptionParameters(deck.sublist("Mesh adaption"));
  if (deck.isSublist("Contact")) {
    scene.contact = adhesion::readContactParameters(deck.sublist("Contact"), "Contact");
  }
  if (deck.isSublist("Adhesion")) {
    scene.adhesion = adhesion::readAdhesionParameters(deck.sublist("Adhesion"), "Adhesion");
    placeLigands(scene);
    requireUsableAdhesion(scene);
  }
  if (deck.isSublist("Tether")) {
    scene.tether = adhesion::readTetherParameters(deck.sublist("Tether"), "Tether");
    requireUsableTether(scene);
  }
  for (const auto& cell : scene.cells) {
    core::require<core::InputError>(!scene.contact.enabled || cell.membraneForces == "Virtual work",
                                    "'Contact/Enabled' is true but '", cell.path,
                                    "/Membrane forces' is 'Contour integral': the contact forces enter "
                                    "as nodal forces, which need 'Virtual work'.");
  }
  return scene;
}

} // namespace capsula::scene
