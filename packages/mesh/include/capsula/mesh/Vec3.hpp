#pragma once
// The small fixed-size types the mesh package speaks in.
//
// Vec3 is Eigen's 3-vector: no alignment requirement (safe in std::vector and
// std::array), no allocation, and readable arithmetic (a.cross(b), a.dot(b)).
// Positions of a whole surface are stored flat (x0, y0, z0, x1, ...) so that a
// solver can hand them over as one array; nodeAt() views one node of such an array.
#include <Eigen/Core>
#include <Eigen/Geometry> // cross()

namespace capsula::mesh {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Node `node` of a flat position array (3 doubles per node), copied into a Vec3.
inline Vec3 nodeAt(const double* positions, int node)
{
  const double* p = positions + 3 * node;
  return Vec3(p[0], p[1], p[2]);
}

} // namespace capsula::mesh
