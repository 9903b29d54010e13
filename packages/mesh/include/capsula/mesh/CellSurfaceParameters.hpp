#pragma once
// A cell's initial surface from deck parameters: shape, size, placement and
// mesh level. The keys are declared here because this is the code that reads
// them; the scene puts them in each "Cells/Cell k" sublist.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <Teuchos_ParameterList.hpp>

#include <array>

namespace capsula::mesh {

/// Declares Shape, Radius, Semi-axes, Center (default `center`), Orientation axis,
/// Orientation angle and Mesh level in `cell`.
void declareCellSurfaceParameters(Teuchos::ParameterList& cell, const std::array<double, 3>& center = {0.0, 0.0, 0.0});

/// Builds the surface a validated cell sublist describes. Throws InputError for
/// combinations a validator cannot see (a spheroid with unequal equatorial
/// semi-axes, a zero orientation axis); `path` (e.g. "Cells/Cell 0") is named.
SurfaceMesh buildCellSurface(const Teuchos::ParameterList& cell, const std::string& path);

} // namespace capsula::mesh
