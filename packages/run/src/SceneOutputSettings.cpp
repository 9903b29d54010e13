#include "capsula/run/SceneOutputSettings.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::run {

namespace core = capsula::core;

namespace {

void declareWallShearStressParameters(Teuchos::ParameterList& wall)
{
  core::declareBool(wall, "Enabled", false,
                    "Compute the principal shear stress on a grid on the wall around the cells at "
                    "every output (thesis eqs 3.59-3.63) and the areas above Threshold upstream and "
                    "downstream of the cell (Figs 5.17-5.22). Needs 'Wall/Enabled'. In a channel "
                    "('Wall/Channel height') the upper wall gets a map of its own (metrics columns "
                    "*_upper, snapshot block upper_wall). Costs four boundary-integral evaluations "
                    "per grid node and wall per output.");
  core::declareReal(wall, "Upstream extent", 6.0,
                    "Length of wall covered upstream of (behind) the centroid of the cells, in cell "
                    "radii.",
                    core::atLeast(0.0));
  core::declareReal(wall, "Downstream extent", 6.0,
                    "Length of wall covered downstream of (ahead of) the centroid of the cells.", core::atLeast(0.0));
  core::declareReal(wall, "Half width", 4.0,
                    "Half the width of the covered strip across the flow (z), centred on the cells.",
                    core::atLeast(0.0));
  core::declareReal(wall, "Spacing", 0.25, "Grid spacing on the wall, in cell radii.", core::greaterThan(0.0));
  core::declareReal(wall, "Threshold", 1.05,
                    "Elevated stress: at least this multiple of the ambient wall stress (1 in units "
                    "of mu k; |k(t)| of the output's instant under 'Flow/Shear rate'); the thesis "
                    "uses 5% above ambient.",
                    core::greaterThan(0.0));
  core::declareRealArray(wall, "Isolated range", {}, 0,
                         "{smallest, largest} wall stress of an isolated cell at the same height "
                         "(wall_stress_min, wall_stress_max of its run); when given, metrics.csv "
                         "gets the wall areas below and above that range (thesis Figs 6.6, 6.12: "
                         "what a pair of cells does to the wall that one cell does not). Empty: "
                         "no comparison.",
                         core::atLeast(0.0));
}

} // namespace

void declareSceneOutputParameters(Teuchos::ParameterList& output)
{
  core::declareString(output, "Directory", "cell3d-output",
                      "Directory for metrics.csv, summary.json, snapshots, checkpoint.h5, deck.xml "
                      "and run.json. --output overrides it.");
  core::declareReal(output, "Interval", 0.25,
                    "Time between outputs (metrics, snapshots, checkpoint); 0: only the start and "
                    "the end.",
                    core::atLeast(0.0));
  core::declareBool(output, "Snapshots", true,
                    "Write HDF5 snapshots of the cell surfaces (positions, velocities, loads, "
                    "tensions) with an XDMF index for ParaView.");
  core::declareInt(output, "Snapshot stride", 1,
                   "Write a snapshot at every n-th output only (metrics are written at every "
                   "output).",
                   1);
  core::declareBool(output, "Fold into box", false,
                    "In a periodic box: draw each cell in the snapshots moved by the lattice vector that brings the "
                    "mean of its nodes into [0, L_x) x R x [0, L_z), whole, with its bonds and tether (metrics and "
                    "checkpoints keep the unfolded positions). Needs 'Domain/Periodic length x' or 'z'.");
  core::declareBool(output, "Checkpoint", true,
                    "Write checkpoint.h5 at every output, so --restart can continue the run.");
  core::declareInt(output, "Progress steps", 20,
                   "Print a progress line every this many accepted steps (and at every output).", 1);
  core::declareRealArray(output, "Flow probes", {}, 0,
                         "Points (x1, y1, z1, x2, y2, z2, ...) where the fluid velocity is written "
                         "to probes.csv at every output (empty: none).");
  declareWallShearStressParameters(
      core::declareSublist(output, "Wall shear stress", "Principal shear stress on the wall."));
  auto& stability =
      core::declareSublist(output, "Stability", "Bounds on the diagnostics of every output (docs/stability.md).");
  core::declareReal(stability, "Minimum angle", 5.0,
                    "Stop the run with an error (keeping the last good checkpoint and outputs) when "
                    "an element's smallest corner angle falls below this many degrees at an "
                    "output: the mesh has degraded past what its quadrature resolves (0: never).",
                    core::atLeast(0.0), core::lessThan(60.0));
  declareSuspensionOutputParameters(core::declareSublist(
      output, "Suspension",
      "The cell-free layer and the hematocrit profile (docs/suspensions.md, section 'Outputs of a run')."));
}

SceneOutputSettings readSceneOutputSettings(const Teuchos::ParameterList& deck, const scene::SceneDescription& scene)
{
  const auto& output = deck.sublist("Output");
  SceneOutputSettings out;
  out.directory = output.get<std::string>("Directory");
  out.interval = output.get<double>("Interval");
  out.snapshots = output.get<bool>("Snapshots");
  out.snapshotStride = output.get<int>("Snapshot stride");
  out.foldIntoBox = output.get<bool>("Fold into box");
  core::require<core::InputError>(!out.foldIntoBox || scene.domain.isPeriodic(), "'Output/Fold into box' = true, but ",
                                  scene.domain.describe(),
                                  " has no periodic direction: set 'Domain/Periodic length x' or 'z', or leave it "
                                  "false.");
  out.checkpoint = output.get<bool>("Checkpoint");
  out.progressSteps = output.get<int>("Progress steps");
  const auto& probes = output.get<Teuchos::Array<double>>("Flow probes");
  core::require<core::InputError>(probes.size() % 3 == 0, "'Output/Flow probes' has ", probes.size(),
                                  " numbers; give whole points, three coordinates each.");
  for (Teuchos::Array<double>::size_type k = 0; k < probes.size(); k += 3) {
    out.flowProbes.emplace_back(probes[k], probes[k + 1], probes[k + 2]);
    const double point[3] = {probes[k], probes[k + 1], probes[k + 2]};
    core::require<core::InputError>(scene.domain.inFluid(point), "'Output/Flow probes' point ", k / 3,
                                    " lies at y = ", probes[k + 1], ", not in the fluid of ", scene.domain.describe(),
                                    ".");
  }
  out.minimumAngle = output.sublist("Stability").get<double>("Minimum angle");
  core::require<core::InputError>(!scene.meshRegularisation.enabled ||
                                      scene.meshRegularisation.triggerAngle > out.minimumAngle,
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
  out.suspension = readSuspensionOutputSettings(output.sublist("Suspension"), scene.domain);
  return out;
}

} // namespace capsula::run
