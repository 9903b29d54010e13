#pragma once
// Tangential redistribution of the nodes of a Lagrangian membrane mesh: the remedy for
// elements that the flow has sheared or stretched (docs/stability.md).
//
// The nodes of a capsule mesh are material points: each carries its position in the
// current configuration x and in the unstressed reference configuration X, and the
// membrane's strain at a point of element e is that of the element map from X to x at the
// same parameter (xi, eta). A redistribution moves nodes along the surface to better-shaped
// elements and gives every moved node the reference position of the material point it
// now sits on, so the elastic state is carried over, not reset:
//
//   1. each vertex near a poor element (RedistributionOptions::improveBelow) moves a
//      fraction `relaxation` of the way to the mean of its vertex
//      neighbours (Laplacian smoothing), with the part of the move along the vertex normal
//      removed;
//   2. the moved point is projected onto the surface as it was before the redistribution,
//      the element maps of the elements near where the node sat (closest point,
//      Gauss-Newton in (xi, eta)); the node's
//      new x and X are then  x = sum_i phi_i(xi, eta) x_i,  X = sum_i phi_i(xi, eta) X_i
//      in the element found, so the node lies on the old surface and is one material point
//      in both configurations;
//   3. each midside node goes to the material point at the middle of its edge in the
//      REFERENCE configuration (the point of the reference surface closest to the mean of
//      its end nodes' new X), with x interpolated the same way: the membrane's element maps
//      are parametrised by the reference, and there they stay regular (a midside node
//      placed at the current middle of a non-uniformly stretched edge would fold them).
//
// All the element maps are those the membrane uses: parametrised by the REFERENCE
// positions (shape parameters alpha, beta, gamma of eq 3.17 from X), so (xi, eta) are
// material coordinates and the interpolation of X is the membrane's own. Every pass
// projects onto the ORIGINAL surface (projecting onto the previous pass's result would
// re-interpolate, and so flatten, a curved surface once per pass) and computes every node
// from the positions before the pass (the result does not depend on the node order).
// A pass is kept only if it raises the smallest angle of the current mesh and keeps the
// reference elements from being squeezed too far. A field that is an affine function of x, X = A x + b, is carried over
// exactly, which the unit tests use.
//
// Volume. The surface through the new nodes differs from the old one by the interpolation
// error of the quadratic elements, and always to the same side: points taken on a curved
// quadratic patch and interpolated again cut its corners, so the enclosed volume shrinks
// (a twisted unit icosphere loses 1.7e-4 of its volume in 3 passes at level 2, 7.4e-6 at
// level 3: about h^4). Left alone this would add up over a long run to a drift
// larger than the time integration's. With `preserveVolume` (the default) the positions
// are then offset along their node normals by the uniform distance that restores the
// enclosed volume (Newton steps with dV = A delta, to round-off), an isotropic dilation of the size of
// the interpolation error; X is not changed by it.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::mesh {

struct RedistributionOptions {
  /// Only the elements whose smallest angle is below this many degrees are worked on: their
  /// vertices and those of the elements around them move, the rest of the mesh stays put
  /// (and is not re-interpolated). 60: the whole mesh.
  double improveBelow = 60.0;
  /// Smoothing passes at most; passes stop early once the smallest angle stops improving.
  int passes = 3;
  /// Fraction (0, 1] of the way to the neighbours' mean a vertex moves per pass.
  double relaxation = 0.5;
  /// A pass is kept only if the reference elements keep a smallest angle of at least
  /// this many degrees (or of what they had, if that was less): moving nodes to better
  /// current elements squeezes the reference ones where the membrane is stretched.
  double minimumReferenceAngle = 15.0;
  /// Restore the enclosed volume by a uniform normal offset after the passes (see above).
  bool preserveVolume = true;
};

struct RedistributedNodes {
  std::vector<double> positions;  ///< x of every node (3 per node), on the old surface
  std::vector<double> reference;  ///< X of the same material points
  int passes = 0;                 ///< passes kept (0: nothing improved, the input returned)
  double minAngleBefore = 0.0;    ///< degrees, smallest vertex-triangle angle of the input
  double minAngleAfter = 0.0;     ///< degrees, of the result
  double referenceMinAngle = 0.0; ///< degrees, smallest angle of the reference elements after
  double maxDisplacement = 0.0;   ///< the largest |x_new - x_old| of any node
  double volumeOffset = 0.0;      ///< the normal offset that restored the volume (0 if off)
};

/// Redistributes the nodes of `mesh` (its topology; positions from `positions`, 3 per
/// node) tangentially, carrying the reference positions `reference` along (see above).
/// Throws InputError for arrays of the wrong size or options out of range.
RedistributedNodes redistributeNodes(const SurfaceMesh& mesh, const std::vector<double>& positions,
                                     const std::vector<double>& reference, const RedistributionOptions& options = {});

/// The point of element `nodes` (shape parameters `parameters`) closest to `target`:
/// Gauss-Newton in (xi, eta), kept inside the parameter triangle. Returns xi, eta and the
/// squared distance.
struct ElementClosestPoint {
  double xi;
  double eta;
  double squaredDistance;
};
ElementClosestPoint closestPointOnElement(const ElementNodes& nodes, const ShapeParameters& parameters,
                                          const Vec3& target);

} // namespace capsula::mesh
