#pragma once
// The deck of a scene: the flow, the wall, N cells, time integration, discretisation
// and outputs.
//
//   Flow/             Capillary number (Ca = mu k a / G), Viscosity ratio (lambda)
//   Wall/             Enabled
//   Cells/Cell 0/     Shape, Radius, Semi-axes, Center, Orientation ..., Mesh level
//                     (capsula::mesh), Membrane law, Shear modulus, Area dilation C,
//                     Prestress, Fixed height
//   Cells/Cell 1/     ... one sublist per cell, numbered from 0
//   Cells/            Minimum gap (between cell surfaces: touching at the start, stop of a run)
//   Time integration/ (capsula::timeint)
//   Discretisation/, Solver/   (capsula::operators)
//   Output/           Directory, Interval, Snapshots, Checkpoint, Progress steps,
//                     Flow probes, Wall shear stress/ (Enabled, extents, Spacing, Threshold)
//
// The valid list depends on the deck: it declares one "Cell k" sublist for every
// "Cell k" the deck has (Cell 0 if none), so a deck with any number of cells validates,
// and a misspelt cell sublist ("Cel 1") is reported as an unknown key.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>

namespace capsula::scene {

/// Declares the keys of one cell in `cell` (the "Cells/Cell k" sublist).
void declareCellParameters(Teuchos::ParameterList& cell);

/// Declares 'Minimum gap' in the "Cells" sublist (read by describeScene; used by the
/// Scene at the start and by runScene after every step).
void declareMinimumGap(Teuchos::ParameterList& cells);

/// Declares the "Output" sublist.
void declareOutputParameters(Teuchos::ParameterList& output);

/// The complete valid parameter list for `deck` (a core::ValidParameterBuilder), named
/// `appName`.
Teuchos::RCP<const Teuchos::ParameterList> validSceneParameters(const Teuchos::ParameterList& deck,
                                                                const std::string& appName);

/// "Cell 0", "Cell 1", ...
std::string cellSublistName(int index);

} // namespace capsula::scene
