#include "capsula/scene/SceneParameters.hpp"

#include "capsula/scene/StiffSolverParameters.hpp"

#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/mesh/AdaptionParameters.hpp>
#include <capsula/mesh/CellSurfaceParameters.hpp>
#include <capsula/mesh/RedistributionParameters.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>

#include <cctype>

namespace capsula::scene {

namespace core = capsula::core;

namespace {

// True for "Cell <digits>" without leading zeros.
bool isCellSublistName(const std::string& name)
{
  const std::string prefix = "Cell ";
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) {
    return false;
  }
  const std::string digits = name.substr(prefix.size());
  for (const char c : digits) {
    if (!std::isdigit(static_cast<unsigned char>(c))) {
      return false;
    }
  }
  return digits.size() == 1 || digits[0] != '0';
}

void declareWallShearStressParameters(Teuchos::ParameterList& wall)
{
  core::declareBool(wall, "Enabled", false,
                    "Compute the principal shear stress on a grid on the wall around the cells at "
                    "every output (thesis eqs 3.59-3.63) and the areas above Threshold upstream and "
                    "downstream of the cell (Figs 5.17-5.22). Needs 'Wall/Enabled'. Costs one "
                    "boundary-integral evaluation per grid node per output.");
  core::declareReal(wall, "Upstream extent", 6.0,
                    "Length of wall covered upstream of (behind) the centroid of the cells, in cell "
                    "radii.",
                    core::atLeast(0.0));
  core::declareReal(wall, "Downstream extent", 6.0,
                    "Length of wall covered downstream of (ahead of) the centroid of the cells.",
                    core::atLeast(0.0));
  core::declareReal(wall, "Half width", 4.0,
                    "Half the width of the covered strip across the flow (z), centred on the cells.",
                    core::atLeast(0.0));
  core::declareReal(wall, "Spacing", 0.25, "Grid spacing on the wall, in cell radii.",
                    core::greaterThan(0.0));
  core::declareReal(wall, "Threshold", 1.05,
                    "Elevated stress: at least this multiple of the ambient wall stress (1 in units "
                    "of mu k); the thesis uses 5% above ambient.",
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

void declareMinimumGap(Teuchos::ParameterList& cells)
{
  core::declareReal(cells, "Minimum gap", 0.05,
                    "Safety distance between cells, in cell radii: cells whose surfaces are no "
                    "farther apart at the start are rejected as touching, and a run stops (after "
                    "writing its outputs and a checkpoint) when two surfaces come closer. The gap "
                    "is measured after every time step on the flat-faceted surfaces "
                    "(packages/scene SurfaceGap.hpp). Below ~0.05 a the film between the cells is "
                    "thinner than the near-singular quadrature and a level-2/3 mesh resolve.",
                    core::greaterThan(0.0));
}

std::string cellSublistName(int index) { return "Cell " + std::to_string(index); }

void declareCellParameters(Teuchos::ParameterList& cell)
{
  mesh::declareCellSurfaceParameters(cell);
  core::declareChoice(cell, "Membrane law", "Skalak", {"NeoHookean", "Skalak"},
                      "Strain energy of the membrane: NeoHookean (eq 3.31) or Skalak (eq 3.32).");
  core::declareChoice(cell, "Membrane forces", "Virtual work", {"Virtual work", "Contour integral"},
                      "How the membrane's load on the fluids is computed. 'Virtual work': nodal "
                      "forces dE/dx of the strain energy and a continuous load interpolated over "
                      "each element (stable for prestressed and stiff-dilation membranes). "
                      "'Contour integral': the thesis's element-averaged load (eq 3.37), which "
                      "folds prestressed membranes at low Ca (docs/validation-cell3d.md).");
  core::declareReal(cell, "Shear modulus", 1.0,
                    "This cell's membrane shear modulus relative to the G of the capillary number "
                    "(1: the cell Ca refers to; 0.5: an activated cell, half as stiff).",
                    core::greaterThan(0.0));
  core::declareReal(cell, "Area dilation C", 2.5,
                    "Skalak law: area-dilation modulus over shear modulus (C G is the dilation "
                    "modulus). The thesis's Chapter 5 spans 0.5 to 2.5. Unused by NeoHookean.",
                    core::greaterThan(0.0));
  core::declareReal(cell, "Prestress", 0.0,
                    "Membrane prestress alpha = a/a0 - 1 (eq 3.45): the unstressed reference shape "
                    "is the initial shape shrunk by 1 + alpha about its centroid (0.05 = 5%).",
                    core::atLeast(0.0), core::lessThan(1.0));
  core::declareBool(cell, "Fixed height", false,
                    "Hold the height of the cell's centroid above the wall fixed (thesis Section "
                    "5.1): the cell's mean vertical velocity is removed from all its nodes.");
}

void declareOutputParameters(Teuchos::ParameterList& output)
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
  core::declareBool(output, "Checkpoint", true,
                    "Write checkpoint.h5 at every output, so --restart can continue the run.");
  core::declareInt(output, "Progress steps", 20,
                   "Print a progress line every this many accepted steps (and at every output).", 1);
  core::declareRealArray(output, "Flow probes", {}, 0,
                         "Points (x1, y1, z1, x2, y2, z2, ...) where the fluid velocity is written "
                         "to probes.csv at every output (empty: none).");
  declareWallShearStressParameters(
    core::declareSublist(output, "Wall shear stress", "Principal shear stress on the wall."));
  auto& stability = core::declareSublist(
    output, "Stability", "Bounds on the diagnostics of every output (docs/stability.md).");
  core::declareReal(stability, "Minimum angle", 5.0,
                    "Stop the run with an error (keeping the last good checkpoint and outputs) when "
                    "an element's smallest corner angle falls below this many degrees at an "
                    "output: the mesh has degraded past what its quadrature resolves (0: never).",
                    core::atLeast(0.0), core::lessThan(60.0));
}

Teuchos::RCP<const Teuchos::ParameterList> validSceneParameters(const Teuchos::ParameterList& deck,
                                                                const std::string& appName)
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList(appName));

  auto& flow = core::declareSublist(*valid, "Flow", "The undisturbed simple shear u = (k y, 0, 0).");
  core::declareReal(flow, "Capillary number", 0.3,
                    "Ca = mu k a / G: shear rate k times external viscosity mu times cell radius a "
                    "over the membrane shear modulus G (eq 3.16).",
                    core::greaterThan(0.0));
  core::declareReal(flow, "Viscosity ratio", 1.0,
                    "lambda = internal / external viscosity. 1 gives the explicit velocity (eq "
                    "3.38 without the double layer); any other value adds the double layer and a "
                    "GMRES solve.",
                    core::greaterThan(0.0));

  auto& wall = core::declareSublist(*valid, "Wall", "The plane wall y = 0 below the flow.");
  core::declareBool(wall, "Enabled", true,
                    "true: the flow is bounded by the wall y = 0 (Blake's kernel, App. B); false: "
                    "unbounded shear (free-space kernel).");

  auto& cells = core::declareSublist(*valid, "Cells", "One sublist per cell: Cell 0, Cell 1, ...");
  declareMinimumGap(cells);
  bool anyCell = false;
  if (deck.isSublist("Cells")) {
    const auto& given = deck.sublist("Cells");
    for (auto it = given.begin(); it != given.end(); ++it) {
      const std::string& name = given.name(it);
      if (given.isSublist(name) && isCellSublistName(name)) {
        declareCellParameters(core::declareSublist(cells, name, "A cell."));
        anyCell = true;
      }
    }
  }
  if (!anyCell) {
    declareCellParameters(core::declareSublist(cells, cellSublistName(0), "A cell."));
  }

  timeint::declareTimeIntegrationParameters(
    core::declareSublist(*valid, "Time integration", "Runge-Kutta time stepping (Section 3.10)."), /*stabilityLimitDefault=*/true);
  operators::declareOperatorParameters(*valid);
  declareStiffSolverParameters(core::declareSublist(
    valid->sublist("Solver"), "Stiff",
    "The linear solves of the stiff time integrators (Time integration/Method ROS34PW2, ROS2, Auto)."));
  mesh::declareRedistributionParameters(core::declareSublist(
    *valid, "Mesh regularisation", "Tangential redistribution of the nodes of a running cell (docs/stability.md)."));
  mesh::declareAdaptionParameters(core::declareSublist(
    *valid, "Mesh adaption", "Curvature-driven refinement of a running cell's mesh (thesis eq 4.3, docs/stability.md)."));
  declareOutputParameters(core::declareSublist(*valid, "Output", "What is written, where and when."));
  return valid;
}

} // namespace capsula::scene
