#pragma once
// A cell's initial surface from deck parameters: shape, size, placement and
// mesh level. The keys are declared here because this is the code that reads
// them; the scene puts them in each "Cells/Cell k" sublist.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <Teuchos_ParameterList.hpp>

namespace capsula::mesh {

/// Declares Shape, Radius, Semi-axes, Center, Orientation axis, Orientation
/// angle and Mesh level in `cell`.
void declareCellSurfaceParameters(Teuchos::ParameterList& cell);

/// Builds the surface a validated cell sublist describes. Throws InputError for
/// combinations a validator cannot see (a spheroid with unequal equatorial
/// semi-axes, a zero orientation axis); `path` (e.g. "Cells/Cell 0") is named.
SurfaceMesh buildCellSurface(const Teuchos::ParameterList& cell, const std::string& path);

} // namespace capsula::mesh
