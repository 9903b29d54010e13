#include "capsula/scene/SceneParameters.hpp"

#include <capsula/adhesion/AdhesionParameters.hpp>
#include <capsula/adhesion/ContactParameters.hpp>
#include <capsula/adhesion/TetherParameters.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/domain/DomainParameters.hpp>
#include <capsula/elasticity/MembraneLawChoice.hpp>
#include <capsula/elasticity/SkalakLaw.hpp>
#include <capsula/mesh/AdaptionParameters.hpp>
#include <capsula/mesh/CellSurfaceParameters.hpp>
#include <capsula/mesh/RedistributionParameters.hpp>
#include <capsula/operators/ShearRate.hpp>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

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

std::string cellSublistName(int index)
{
  return "Cell " + std::to_string(index);
}

bool isCellTypeName(const std::string& name)
{
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) {
    return false;
  }
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::array<double, 3> defaultCellCenter(int index, int count)
{
  return {2.5 * index - 1.25 * (count - 1), 1.6, 0.0};
}

void declareCellParameters(Teuchos::ParameterList& cell, const std::array<double, 3>& center,
                           const elasticity::MembraneLawRegistry& laws)
{
  mesh::declareCellSurfaceParameters(cell, center);
  core::declareString(cell, "Type", "",
                      "The cell's type, a word (red_cell, platelet): the suspension outputs give each type "
                      "its own columns and distributions (docs/suspension3d.md). suspension3d sets it to "
                      "the name of the cell's 'Suspension/Cell types' sublist; empty: no type.");
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
  core::declareReal(cell, "Prestress", 0.0,
                    "Membrane prestress alpha = a/a0 - 1 (eq 3.45): the unstressed reference shape "
                    "is the initial shape shrunk by 1 + alpha about its centroid (0.05 = 5%).",
                    core::atLeast(0.0), core::lessThan(1.0));
  core::declareReal(cell, "Bending modulus", 0.0,
                    "E_b = k_b / (G a^2): the membrane's bending modulus k_b over the G of the "
                    "capillary number times the cell radius squared (Helfrich energy (k_b/2) int "
                    "(2H - c0)^2 dA, docs/membrane-forces.md). 0 builds no bending term. A red cell "
                    "has E_b ~ 0.005-0.03 (k_b ~ 2e-19 J, G ~ 5e-6 N/m, a ~ 2.8 um). Needs 'Membrane "
                    "forces' = 'Virtual work'. At most 1e100 Ca / (|c0| + 1/l3)^3 (l3 the smallest "
                    "semi-axis of the cell): beyond it the bending loads overflow the run's arithmetic.",
                    core::atLeast(0.0));
  core::declareReal(cell, "Spontaneous curvature", 0.0,
                    "c0 a: the total curvature 2H at which the membrane carries no bending moment, "
                    "times the cell radius (outward normal: a sphere of radius R has 2H = 2/R, so a "
                    "sphere with c0 = 2/R is free of bending moments). Needs a 'Bending modulus' > 0 "
                    "and 'Bending reference' = 'Flat'. |c0| at most (1e100 Ca / E_b)^(1/3) - 1/l3 (l3 "
                    "the smallest semi-axis of the cell): beyond it the bending loads overflow.");
  core::declareChoice(cell, "Bending reference", "Flat", {"Flat", "Initial shape"},
                      "The curvature at which the bending energy vanishes. 'Flat': the spontaneous "
                      "curvature c0 everywhere. 'Initial shape': each material point's own 2H in "
                      "the cell's initial shape, so that the shape the deck builds (a biconcave red "
                      "cell, say) is free of bending moments. 'Initial shape' needs a 'Bending modulus' "
                      "> 0 (refused without it, as a key without effect).");
  core::declareReal(cell, "Viscosity ratio", 0.0,
                    "lambda of this cell (its internal viscosity over the external one), for suspensions of "
                    "cells of different kinds (red cells at 5, platelets at 1). 0, the default: "
                    "'Flow/Viscosity ratio'. A scene where any cell has lambda != 1 adds the double layer "
                    "and a Krylov solve ('Solver/Method').",
                    core::atLeast(0.0));
  core::declareBool(cell, "Fixed height", false,
                    "Hold the height of the cell's centroid above the wall fixed (thesis Section "
                    "5.1): the cell's mean vertical velocity is removed from all its nodes.");
  core::declareBool(cell, "Conserve volume", false,
                    "Remove the net normal flux of the cell's node velocities through its surface at "
                    "every stage (scene/VolumeConstraint.hpp), so that the enclosed volume is held to "
                    "the accuracy of the time integration. For stiff cells close to the wall, whose "
                    "volume the quadrature error of the single layer there otherwise changes by "
                    "percents (docs/cell3d-adhesion-results.md).");
  // Last, so that a law's key that would replace one of the cell's is refused.
  elasticity::declareMembraneLawParameters(cell, laws.infos(), elasticity::SkalakLaw::registeredName,
                                           "Strain energy of the membrane.");
}

void declareSceneParameters(Teuchos::ParameterList& valid, const Teuchos::ParameterList& deck, int cellsWhenNoneGiven,
                            const elasticity::MembraneLawRegistry& laws)
{
  auto& flow = core::declareSublist(valid, "Flow",
                                    "The undisturbed flow u = (k(t) f(y), 0, 0): simple shear, plane Couette or "
                                    "plane Poiseuille flow ('Flow/Profile').");
  core::declareReal(flow, "Capillary number", 0.3,
                    "Ca = mu k a / G: shear rate k times external viscosity mu times cell radius a "
                    "over the membrane shear modulus G (eq 3.16).",
                    core::greaterThan(0.0));
  core::declareReal(flow, "Viscosity ratio", 1.0,
                    "lambda = internal / external viscosity, of every cell without a 'Viscosity ratio' of its "
                    "own. 1 gives the explicit velocity (eq 3.38 without the double layer); any other value "
                    "adds the double layer and a Krylov solve ('Solver/Method').",
                    core::greaterThan(0.0));
  operators::declareShearRateParameters(core::declareSublist(
      flow, "Shear rate", "The shear rate k(t) over its mean: steady, pulsatile or a tabulated waveform."));

  domain::declareDomainParameters(valid);
  auto& wall = valid.sublist("Wall");
  core::declareReal(wall, "Minimum gap", 0.025,
                    "Safety distance between a cell and the wall at the start, in cell radii: a "
                    "new run whose lowest node is no higher (in a channel: whose highest node is no "
                    "farther below the upper wall) is rejected (a restart is not checked "
                    "again). The cell's image below the wall lies twice as far, so the default "
                    "keeps it as far as 'Cells/Minimum gap' keeps two cells. 0 refuses only a cell "
                    "on or through the wall.",
                    core::atLeast(0.0));

  adhesion::declareContactParameters(core::declareSublist(
      valid, "Contact",
      "Short-range repulsion that keeps membranes off the wall and off each other (packages/adhesion "
      "ContactRepulsion.hpp); off by default."));
  adhesion::declareAdhesionParameters(core::declareSublist(
      valid, "Adhesion",
      "Receptor-ligand bonds between each membrane and a ligand-coated wall y = 0 (packages/adhesion, "
      "docs/cell3d.md); off by default. Needs the wall and 'Membrane forces' = 'Virtual work'."));

  adhesion::declareTetherParameters(core::declareSublist(
      valid, "Tether",
      "One permanent bond from a material point of a cell's membrane to a fixed anchor on the wall y = 0 "
      "(packages/adhesion Tether.hpp, docs/cell3d.md); off by default. Needs the wall and 'Membrane forces' = "
      "'Virtual work'."));

  auto& cells = core::declareSublist(valid, "Cells", "One sublist per cell: Cell 0, Cell 1, ...");
  declareMinimumGap(cells);
  std::vector<std::string> given;
  if (deck.isSublist("Cells")) {
    const auto& list = deck.sublist("Cells");
    for (auto it = list.begin(); it != list.end(); ++it) {
      if (list.isSublist(list.name(it)) && isCellSublistName(list.name(it))) {
        given.push_back(list.name(it));
      }
    }
  }
  if (given.empty()) {
    for (int k = 0; k < cellsWhenNoneGiven; ++k) {
      given.push_back(cellSublistName(k));
    }
  }
  const int count = static_cast<int>(given.size());
  for (const auto& name : given) {
    // An index too long for an int is refused later (describeScene wants Cell 0 .. Cell n-1).
    const std::string digits = name.substr(std::string("Cell ").size());
    const int index = digits.size() > 6 ? count : std::stoi(digits);
    declareCellParameters(core::declareSublist(cells, name, "A cell."), defaultCellCenter(index, count), laws);
  }
}

void declareMeshEvolutionParameters(Teuchos::ParameterList& valid)
{
  mesh::declareRedistributionParameters(core::declareSublist(
      valid, "Mesh regularisation", "Tangential redistribution of the nodes of a running cell (docs/stability.md)."));
  mesh::declareAdaptionParameters(
      core::declareSublist(valid, "Mesh adaption",
                           "Curvature-driven refinement of a running cell's mesh (thesis eq 4.3, docs/stability.md)."));
}

} // namespace capsula::scene
