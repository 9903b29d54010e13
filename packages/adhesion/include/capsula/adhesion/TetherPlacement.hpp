#pragma once
// Where a tether holds a membrane: the material point farthest along a direction (the
// lowest point for the downward vertical), and the patch of material points around it that
// shares the tether's force (TetherParameters.hpp, 'Patch radius').
//
// Farthest point: on each 6-node element x(xi, eta) . d is a quadratic polynomial in (xi,
// eta) (the shape functions are quadratic), so its maximum over the element is exact: the
// largest of its values at the interior stationary point, at the stationary point of each
// edge and at the three vertices. Over the mesh the first element (lowest index) with the
// largest value wins, so every rank finds the same material point.
//
// Patch: the points of the 7-point triangle rule of every element within rho of the centre
// point, each weighted by its area share w_q h_s times the bump (1 - r^2 / rho^2)^2, r its
// distance from the centre; the weights are normalised to sum to 1. rho = 0: the centre
// point alone, weight 1.
#include "capsula/adhesion/Receptors.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <vector>

namespace capsula::adhesion {

/// The material point of `mesh` at node positions `positions` (3 per node) farthest along
/// `direction`, in the parametrisation `points` gives each element (its reference shape's).
Receptor farthestMaterialPoint(const mesh::SurfaceMesh& mesh, const double* positions, const ReceptorSet& points,
                               const mesh::Vec3& direction);

/// Material points and their weights (summing to 1).
struct WeightedPoints {
  std::vector<Receptor> points;
  std::vector<double> weights;
};

/// The patch of radius `radius` around `centre` (see above), at node positions `positions`,
/// in the parametrisation of `points`.
WeightedPoints materialPatch(const mesh::SurfaceMesh& mesh, const double* positions, const ReceptorSet& points,
                             const Receptor& centre, double radius);

} // namespace capsula::adhesion
