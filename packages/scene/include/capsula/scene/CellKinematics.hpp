#pragma once
// Instantaneous motion of a cell from the velocities of its nodes.
//
// Centroid velocity: the rate of change of x_c = (1/V) int_V x dV under the surface
// velocity u (Reynolds transport theorem, with V constant to first order):
//     dx_c/dt = (1/V) int_S (x - x_c) (u . n) dS,
// u interpolated over each element by the same shape functions as the positions (eq
// 3.18). It is exact for rigid motions, and a uniform velocity w gives exactly w
// (int_S x n^T dS = V I and int_S n dS = 0 for a closed surface), which is what the
// fixed-height constraint relies on. It also gives the slip and migration velocities
// at one instant, next to the spline derivative of thesis Section 3.11.2.
//
// Rigid-body fit: the translation U and rotation rate Omega minimising
// sum_i |u_i - U - Omega x (x_i - x_c)|^2 over the nodes. For a tank-treading capsule
// Omega is the rate at which the membrane turns, for a rigid sphere its angular velocity.
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

namespace capsula::scene {

/// dx_c/dt of the cell whose nodes move with `nodeVelocities` (3 per node, the mesh's
/// numbering); N_Q = 12 integrates the degree-6 integrand exactly for polynomial u.
mesh::Vec3 centroidVelocity(const mesh::SurfaceMesh& cell, const double* nodeVelocities, int numQuadraturePoints = 12);

struct RigidMotion {
  mesh::Vec3 translation = mesh::Vec3::Zero(); ///< U, velocity of the reference point
  mesh::Vec3 rotation = mesh::Vec3::Zero();    ///< Omega
};

/// Least-squares rigid motion of the nodes about `referencePoint` (usually the centroid).
RigidMotion rigidMotionFit(const mesh::SurfaceMesh& cell, const double* nodeVelocities,
                           const mesh::Vec3& referencePoint);

} // namespace capsula::scene
