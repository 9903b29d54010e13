#include <capsula/mesh/Placement.hpp>

#include <capsula/core/Error.hpp>

#include <Eigen/Geometry>

#include <vector>

namespace capsula::mesh {

Mat3 rotationAboutAxis(const Vec3& axis, double angle)
{
  core::require<core::InputError>(axis.norm() > 0.0, "rotationAboutAxis: the axis is the zero vector");
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

void applyPlacement(SurfaceMesh& mesh, const Placement& placement)
{
  const Mat3& r = placement.rotation;
  // Round-off of a rotation built from angles is ~1e-16; 1e-10 only rejects real mistakes.
  core::require<core::InputError>((r.transpose() * r - Mat3::Identity()).norm() < 1e-10 && r.determinant() > 0.0,
                                  "Placement: the rotation matrix is not a proper rotation "
                                  "(orthogonal with determinant +1)");
  std::vector<double> x = mesh.positions();
  for (int node = 0; node < mesh.numNodes(); ++node) {
    Eigen::Map<Vec3> p(x.data() + 3 * node);
    const Vec3 body = p;
    p = placement.centre + r * body;
  }
  mesh.setPositions(x);
}

} // namespace capsula::mesh
