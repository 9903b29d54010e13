#pragma once
// The deck's "Tether" sublist: one permanent bond, a linear spring that never breaks,
// between a chosen material point of one cell's membrane and a fixed anchor on the wall
// y = 0 (the 3D counterpart of the tethered 2D cell of thesis Chapter 4; Tether.hpp).
//
// Units are those of the capillary number Ca = mu k a / G, as for the bonds
// (AdhesionParameters.hpp): lengths in cell radii a, the spring constant in G, forces in G a.
#include <capsula/mesh/Vec3.hpp>

#include <Teuchos_ParameterList.hpp>

#include <optional>
#include <string>

namespace capsula::adhesion {

struct TetherSettings {
  bool enabled = false;
  int cell = 0;                     ///< the tethered cell, 'Cells/Cell <cell>'
  double polarAngle = 0.0;          ///< degrees from the downward vertical -y: 0 is the lowest point
  double azimuth = 0.0;             ///< degrees in the wall plane, from +x (downstream) towards +z
  double springConstant = 100.0;    ///< sigma / G
  std::optional<double> restLength; ///< lambda / a; none: the tether's length at t = 0
  std::optional<mesh::Vec3> anchor; ///< on the wall; none: directly below the attachment at t = 0
  double patchRadius = 0.0;         ///< rho / a; 0: one material point
  /// The unit vector from the cell's centre towards the attachment point.
  mesh::Vec3 direction() const;
};

/// Declares Enabled, Cell, Polar angle, Azimuth, Spring constant, Rest length, Anchor and
/// Patch radius.
void declareTetherParameters(Teuchos::ParameterList& tether);

/// Reads a validated sublist; `path` names it in messages ("Tether"). Throws
/// core::InputError, naming the key, for a spring constant <= 0 with the tether enabled, a
/// rest length or an anchor that is not one value or a point {x, y, z} on the wall y = 0,
/// and values a list built in code has not had validated (negative radius, angle out of
/// range).
TetherSettings readTetherParameters(const Teuchos::ParameterList& tether, const std::string& path = "Tether");

} // namespace capsula::adhesion
