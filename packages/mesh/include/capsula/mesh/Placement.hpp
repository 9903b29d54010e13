#pragma once
// Where a shape sits: a rigid motion x_lab = centre + rotation * x_body.
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

namespace capsula::mesh {

struct Placement {
  Vec3 centre = Vec3::Zero();
  Mat3 rotation = Mat3::Identity(); ///< proper rotation (orthogonal, det +1), body to lab
};

/// Rotation by `angle` (radians, right-handed) about `axis` (any nonzero length).
Mat3 rotationAboutAxis(const Vec3& axis, double angle);

/// Applies the rigid motion to every node of `mesh`. Throws InputError if the
/// rotation is not a proper rotation (that would break the outward orientation).
void applyPlacement(SurfaceMesh& mesh, const Placement& placement);

} // namespace capsula::mesh
