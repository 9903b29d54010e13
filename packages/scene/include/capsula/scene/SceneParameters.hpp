#pragma once
// The deck keys of a scene's physical model:
//
//   Flow/             Capillary number (Ca = mu k a / G), Viscosity ratio (lambda)
//   Wall/             Enabled
//   Cells/Cell 0/     Shape, Radius, Semi-axes, Center, Orientation ..., Mesh level
//                     (capsula::mesh), Membrane law and its law's keys (Area dilation C
//                     of Skalak; elasticity/MembraneLawRegistry.hpp), Shear modulus, Prestress, Bending modulus, Spontaneous curvature, Bending
//                     reference, Fixed height
//   Cells/Cell 1/     ... one sublist per cell, numbered from 0
//   Cells/            Minimum gap (between cell surfaces: touching at the start, stop of a run)
//   Contact/          Enabled, Range, Strength (capsula::adhesion: the short-range repulsion)
//   Adhesion/         Enabled, Receptor density, Ligand density, Ligand patch, Spring constant,
//                     ..., Kinetics, Seed (capsula::adhesion: receptor-ligand bonds to the wall)
//   Tether/           Enabled, Cell, Polar angle, Azimuth, Anchor, Patch radius, Spring
//                     constant, Rest length (capsula::adhesion: one permanent bond to the wall)
//   Mesh regularisation/, Mesh adaption/   (capsula::mesh)
//
// The run adds Time integration (capsula::timeint), Discretisation and Solver
// (capsula::operators) and Output (run/SceneOutputSettings.hpp); run/SceneRunDeck.hpp
// assembles the whole deck of cell3d and twocell3d.
//
// The valid list depends on the deck: it declares one "Cell k" sublist for every
// "Cell k" the deck has (Cell 0 if none), so a deck with any number of cells validates,
// and a misspelt cell sublist ("Cel 1") is reported as an unknown key.
#include <capsula/elasticity/MembraneLawRegistry.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <array>
#include <string>

namespace capsula::scene {

/// Declares the keys of one cell in `cell` (the "Cells/Cell k" sublist), its Center
/// defaulting to `center`; 'Membrane law' chooses among `laws` (default Skalak).
void declareCellParameters(Teuchos::ParameterList& cell, const std::array<double, 3>& center = {0.0, 0.0, 0.0},
                           const elasticity::MembraneLawRegistry& laws = elasticity::builtInMembraneLaws());

/// The default Center of cell `index` of `count`: at the demo's height 1.6 above the wall,
/// in line along the flow 2.5 radii apart (a gap of 0.5) and centred on x = 0, so that a
/// deck that leaves out the centres (the one --print-defaults prints) runs.
std::array<double, 3> defaultCellCenter(int index, int count);

/// Declares 'Minimum gap' in the "Cells" sublist (read by describeScene; used by the
/// Scene at the start and by the run after every step).
void declareMinimumGap(Teuchos::ParameterList& cells);

/// Declares the sublists Flow, Wall and Cells (with a "Cell k" sublist for every one
/// `deck` has, or `cellsWhenNoneGiven` of them when it has none) in `valid`; each cell's
/// 'Membrane law' chooses among `laws`.
void declareSceneParameters(Teuchos::ParameterList& valid, const Teuchos::ParameterList& deck,
                            int cellsWhenNoneGiven = 1,
                            const elasticity::MembraneLawRegistry& laws = elasticity::builtInMembraneLaws());

/// Declares the sublists Mesh regularisation and Mesh adaption in `valid`.
void declareMeshEvolutionParameters(Teuchos::ParameterList& valid);

/// "Cell 0", "Cell 1", ...
std::string cellSublistName(int index);

/// Whether `name` can be a cell's 'Type': a word (a letter, then letters, digits or
/// underscores), since the outputs name columns after it.
bool isCellTypeName(const std::string& name);

} // namespace capsula::scene
