#pragma once
// Diagnostics of the numerical health of one cell at an output time (docs/stability.md): how far
// its mesh has degraded, whether its membrane is in compression (the precursor of
// buckling), and how well the gap to the wall is resolved. Observers compute them at
// output times, never inside the right-hand side; they cost one pass over the elements.
#include <capsula/domain/Domain.hpp>
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

namespace capsula::scene {

struct CellStability {
  /// The smallest corner angle of the flat vertex triangles, degrees (60 for an
  /// equilateral element; the level-1 icosphere starts at 55.6).
  double minAngleDegrees = 0.0;
  /// The largest ratio longest / shortest vertex-to-vertex edge of one element (>= 1).
  double maxEdgeRatio = 1.0;
  /// The smallest principal tension over the nodes (eq 3.30). Negative: the membrane is
  /// compressed there and a thin shell would buckle (thesis Section 3.7: below Ca ~ 0.3
  /// without prestress, Lac et al. 2004); without a bending modulus nothing stops the
  /// wrinkles that follow at the grid scale.
  double mostCompressiveTension = 0.0;
  /// The smallest distance of a node to the nearer wall of the domain (either wall of a
  /// channel) divided by the local element size: the longest vertex-to-vertex edge of the
  /// elements around that node. Below ~1 the near-singular quadrature of the wall image has
  /// to resolve a gap thinner than an element; <= 0 means the cell crossed the wall. Without
  /// a wall it is the lowest node's height above y = 0 (the plane where the shear flow is at
  /// rest) and says nothing about contact.
  double wallGapPerElementSize = 0.0;
  /// The largest element distortion: how far a midside node has slid along its edge from
  /// the middle, max |alpha - 1/2| (eq 3.17; 0 on the icosphere, 1/2 when an edge
  /// collapses onto its midside node). Tank-treading carries midside nodes along the edges.
  double maxDistortion = 0.0;
  /// The smallest principal stiffness d2w/dlambda_i^2 of the membrane law over the nodes, in
  /// units of G (elasticity/PrincipalStiffness.hpp; 2 (1 + C) for Skalak and 4 for
  /// neo-Hookean at rest). Negative: the law softens there under further compression, and
  /// the compressed material crowds into the narrowest strip the mesh allows, the element
  /// (Skalak below a principal stretch of 0.58 at the other stretch 1, for every C).
  double minPrincipalStiffness = 0.0;
};

/// What CellStability takes from a membrane evaluated at the cell's positions (its owner's,
/// Scene.hpp): the two numbers that travel to the other ranks.
struct MembraneExtremes {
  double mostCompressiveTension = 0.0;  ///< CellStability::mostCompressiveTension
  double leastPrincipalStiffness = 0.0; ///< over the shear modulus: CellStability::minPrincipalStiffness
};

/// The extremes of `membrane` at its latest evaluation.
MembraneExtremes membraneExtremes(const elasticity::MembraneMechanics& membrane);

/// The diagnostics of `cell` (at its current positions) with the extremes of its membrane
/// evaluated there, the wall gap in `domain`.
CellStability measureStability(const mesh::SurfaceMesh& cell, const MembraneExtremes& membrane,
                               const domain::Domain& domain);

/// The same with the membrane itself.
CellStability measureStability(const mesh::SurfaceMesh& cell, const elasticity::MembraneMechanics& membrane,
                               const domain::Domain& domain);

/// The longest vertex-to-vertex edge over the elements that contain `node`.
double localElementSize(const mesh::SurfaceMesh& cell, int node);

} // namespace capsula::scene
