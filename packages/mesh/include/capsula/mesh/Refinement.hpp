#pragma once
// Local refinement of a quadratic-triangle mesh that keeps it conforming (thesis
// Section 4.7): red-green-blue refinement with longest-edge closure, and quadratic node
// placement.
//
// Each element's reference edge is its longest (vertex to vertex). Marked elements have
// all three edges refined; then, until nothing changes, any element with a refined edge
// gets its longest edge refined too. Each element is then split by its refined edges:
//   none           Kept;
//   longest only   Green: bisected from the opposite vertex to the longest edge's
//                  (old) midside node, two children;
//   longest + one  Blue: the green bisection, then the half that holds the other refined
//                  edge bisected across it from the new vertex, three children;
//   all three      Red: four children, the parent's vertices and midside nodes as their
//                  vertices.
// Refinement spreads only along longest edges (a few elements), never to the whole
// mesh, and the quality stays bounded over any number of passes: longest-edge bisection
// never produces an angle below half the smallest angle of the triangle it started from
// (Rivara 1984), nor does the blue split (one half of Rivara's 4T-LE partition;
// unit-tested), and red children are similar to their parent. So the smallest angle of
// the mesh stays above half that of the initial mesh. Funken, Praetorius & Wissgott
// (2011) use the same red-green-blue closure for linear triangles.
//
// Placement. Every new node is a midside node of a child edge, placed on the parent's
// quadratic map x(xi, eta) (eq 3.20) at the parametric midpoint of that edge's ends. A
// node on an old edge is shared by the two elements across it: both maps reduce there to
// the curve through the edge's three nodes, so they place it alike.
//
// Fields. Any number of per-node fields (reference positions, velocities, ...) are carried
// over with the SAME parent map as the positions: for a new node at (xi, eta) of parent
// element e, f_new = sum_i phi_i(xi, eta) f_i over the parent's six nodes, for every field
// and for the positions alike. So the new node is one material point in every
// configuration. The map's parametrisation (alpha, beta, gamma, eq 3.17) is that of the
// mesh's own positions; to parametrise by another configuration (say the reference), pass
// a mesh holding those positions and the current positions as a field.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <cstdint>
#include <vector>

namespace capsula::mesh {

/// What happens to one element of the old mesh.
enum class ElementSplit : std::uint8_t { Kept, Green, Blue, Red };

/// The conforming closure of a set of marked elements (see above). Throws InputError for
/// an element index out of range.
std::vector<ElementSplit> refinementPlan(const SurfaceMesh& mesh, const std::vector<int>& markedElements);

/// The refined mesh and what came with it.
struct RefinedMesh {
  /// Nodes 0 .. N-1 are the old nodes, unchanged (old midside nodes of refined edges are
  /// vertices now); the new midside nodes follow.
  SurfaceMesh mesh;
  /// The input fields on the new nodes, in the input order, same layout (components per
  /// node = old size / old number of nodes).
  std::vector<std::vector<double>> fields;
  /// parentElement[e] = the old element new element e lies in. Children follow their
  /// parents' order; a kept element is its own only child.
  std::vector<int> parentElement;
  /// How each old element was split.
  std::vector<ElementSplit> splits;
};

/// Refines `markedElements` (red) and their conforming closure (see above). Each field
/// must hold the same number of values (>= 1) for every node of `mesh`.
RefinedMesh refineElements(const SurfaceMesh& mesh, const std::vector<int>& markedElements,
                           const std::vector<std::vector<double>>& fields = {});

} // namespace capsula::mesh
