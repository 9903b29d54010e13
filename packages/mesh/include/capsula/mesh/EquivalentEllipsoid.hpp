#pragma once
// The ellipsoid with the same inertia as the cell, and the Taylor deformation
// parameters built from it (thesis Section 3.11.1).
//
// The thesis equates the eigenvalues of the VOLUME inertia tensor of the cell
// (uniform density, eq 3.52) with those of a solid ellipsoid of the same volume,
// (V/5)(l2^2 + l3^2) etc. (eq 3.53). Equivalently, with the second moment
// M = int_V (x - x_c)(x - x_c)^T dV = I_trace - I, an ellipsoid has M = (V/5) diag(l^2),
// so l_i = sqrt(5 mu_i / V) for the eigenvalues mu_i of M. That is what is computed,
// about the centroid, so the result does not depend on where the cell is; an exact
// ellipsoid returns its own semi-axes.
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

namespace capsula::mesh {

/// Volume inertia tensor about the centroid, unit density (eq 3.52 with the ERRATA's
/// (3,3) entry x^2 + y^2). Computed from M_ij = 1/5 int_S y_i y_j (y . n) dS, y = x - x_c
/// (divergence of y_i y_j y = 5 y_i y_j), which is eq 3.52 in one symmetric form; the
/// integrand has degree 8, so even N_Q = 13 (degree 7) is not exact, only very close.
Mat3 inertiaTensor(const SurfaceMesh& mesh, int numQuadraturePoints = 13);

struct EquivalentEllipsoid {
  Vec3 semiAxes; ///< l1 >= l2 >= l3
  Mat3 axes;     ///< column i is the unit direction of semi-axis i (a proper rotation)
  Vec3 centre;   ///< the centroid
  double volume; ///< the cell's (and the ellipsoid's) volume
};

/// Semi-axes and directions of the ellipsoid with the cell's volume and inertia.
EquivalentEllipsoid equivalentEllipsoid(const SurfaceMesh& mesh, int numQuadraturePoints = 13);

/// Taylor deformation parameter D_ij = (l_i - l_j)/(l_i + l_j) (eq 3.51); with the
/// semi-axes in descending order D_ij >= 0 for i < j.
inline double taylorDeformation(double li, double lj)
{
  return (li - lj) / (li + lj);
}

/// (D12, D13, D23) of an equivalent ellipsoid.
inline Vec3 taylorDeformations(const EquivalentEllipsoid& ellipsoid)
{
  const Vec3& l = ellipsoid.semiAxes;
  return Vec3(taylorDeformation(l[0], l[1]), taylorDeformation(l[0], l[2]), taylorDeformation(l[1], l[2]));
}

} // namespace capsula::mesh
