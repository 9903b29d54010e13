#pragma once
// A wall of the domain as the membrane forces see it: the plane y = height with the fluid on
// one side. The lower wall is {0, +1}; a channel's upper wall {H, -1}. Contact repels
// membranes from every wall (ContactRepulsion.hpp); bonds tie them to the one wall that
// carries ligands (AdhesionParameters.hpp, 'Adhesion/Ligand wall').
#include <capsula/mesh/Vec3.hpp>

namespace capsula::adhesion {

struct WallPlane {
  double height = 0.0;
  int fluidSide = 1; ///< +1: the fluid lies above the plane (the lower wall); -1: below it

  /// The gap of a point at height y, positive in the fluid.
  double gap(double y) const { return fluidSide * (y - height); }
  /// The point of the plane nearest to x (a new bond's anchor).
  mesh::Vec3 foot(const mesh::Vec3& x) const { return mesh::Vec3(x[0], height, x[2]); }
};

} // namespace capsula::adhesion
