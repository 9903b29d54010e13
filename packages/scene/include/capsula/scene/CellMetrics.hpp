#pragma once
// The metrics of one cell at one output time (thesis Section 3.11 and Chapter 5):
// deformation, position, size, footprint and the stress its membrane carries. Computed
// by observers at output times, never inside the right-hand side.
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/scene/ShearDeformation.hpp>

namespace capsula::scene {

struct CellShape {
  ShearDeformation deformation;             ///< D12, D13, D23, inclination (eq 3.51)
  mesh::Vec3 centroid = mesh::Vec3::Zero(); ///< x_c (eq 3.54, ERRATA form)
  double volume = 0.0;
  double area = 0.0;
  double reducedVolume = 0.0; ///< eq 5.1
  double footprintXZ = 0.0;   ///< projected area on the wall plane, A_xz (Section 5.2.1)
};

/// The shape metrics of the cell at its current positions. Each integral uses the rule
/// that is exact (or nearly) for it on the discrete surface, independent of the deck's
/// N_Q: volume 6, centroid 12, equivalent ellipsoid 13, area and footprint 7 points.
CellShape measureShape(const mesh::SurfaceMesh& cell);

/// The principal shear stress sigma_SS = |Delta f| on the membrane (eq 3.57), from the
/// element-averaged loads <Delta f>_m (3 per element, the cell's element numbering).
struct MembraneStress {
  double mean = 0.0;    ///< area-weighted mean over the surface, sum A_m |f_m| / sum A_m
  double maximum = 0.0; ///< largest element value
};

MembraneStress membraneStress(const mesh::SurfaceMesh& cell, const double* elementLoads);

} // namespace capsula::scene
