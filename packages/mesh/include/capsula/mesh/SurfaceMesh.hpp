#pragma once
// A closed surface of 6-node quadratic triangles (thesis Section 3.3).
//
// Topology (connectivity, node-to-element incidence, edges, node kinds) is fixed
// when the mesh is built; node positions change every time step and live in one
// flat array (x0, y0, z0, x1, y1, z1, ...) that the solver reads and writes whole.
//
// Conventions:
//   element nodes  {v0, v1, v2, m01, m12, m20}: three vertices, then the midside
//                  nodes of edges v0-v1, v1-v2, v2-v0 (the thesis's x1..x6);
//   local edge k   k = 0: v0-v1 (midside local node 3), 1: v1-v2 (node 4),
//                  2: v2-v0 (node 5);
//   orientation    (x_xi cross x_eta), i.e. (v1 - v0) x (v2 - v0), points out of
//                  the enclosed volume; every edge is traversed in opposite
//                  directions by its two elements.
// The constructor checks that the connectivity describes a closed, consistently
// oriented 2-manifold and throws capsula::core::InputError otherwise.
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace capsula::mesh {

using ElementConnectivity = std::array<int, 6>;

/// Whether a node is an element vertex or a midside (edge) node.
enum class NodeKind : std::uint8_t { Vertex, Edge };

/// One element that touches a node, and where the node sits in it.
struct NodeIncidence {
  int element;
  int localNode; ///< 0..5
};

/// An element edge: two vertices, the midside node between them, the two elements.
struct Edge {
  std::array<int, 2> vertices;   ///< end nodes, in the direction elements[0] traverses them
  int midNode;                   ///< the midside node on this edge
  std::array<int, 2> elements;   ///< the two elements sharing the edge
  std::array<int, 2> localEdges; ///< the edge's local index (0..2) in each element
};

/// A contiguous read-only range (a std::span stand-in for C++17).
template <typename T>
struct ConstRange {
  const T* first;
  const T* last;
  const T* begin() const { return first; }
  const T* end() const { return last; }
  std::size_t size() const { return static_cast<std::size_t>(last - first); }
  const T& operator[](std::size_t i) const { return first[i]; }
};

class SurfaceMesh {
public:
  /// Builds the topology from `positions` (3 doubles per node) and the element
  /// connectivity. Throws InputError unless the elements form a closed,
  /// consistently oriented surface in which every node is either a vertex or a
  /// midside node (never both) and every edge has one midside node.
  SurfaceMesh(std::vector<double> positions, std::vector<ElementConnectivity> elements);

  int numNodes() const { return static_cast<int>(positions_.size() / 3); }
  int numElements() const { return static_cast<int>(elements_.size()); }
  int numEdges() const { return static_cast<int>(edges_.size()); }
  int numVertexNodes() const { return numVertexNodes_; }

  // --- positions ----------------------------------------------------------
  /// All positions, flat: 3 * numNodes() doubles.
  const std::vector<double>& positions() const { return positions_; }
  const double* positionData() const { return positions_.data(); }
  /// Replaces all positions; `positions` must hold 3 * numNodes() doubles.
  void setPositions(const std::vector<double>& positions);
  void setPositions(const double* positions);
  Vec3 position(int node) const { return nodeAt(positions_.data(), node); }
  void setPosition(int node, const Vec3& x);

  // --- elements -----------------------------------------------------------
  const ElementConnectivity& element(int e) const { return elements_[e]; }
  const std::vector<ElementConnectivity>& elements() const { return elements_; }
  /// The six node positions of element e, from the mesh's own positions.
  ElementNodes elementNodes(int e) const { return gatherElementNodes(element(e), positions_.data()); }
  /// The six node positions of element e, from another flat position array
  /// with the same node numbering (a reference or trial configuration).
  ElementNodes elementNodes(int e, const double* positions) const { return gatherElementNodes(element(e), positions); }

  // --- nodes ----------------------------------------------------------------
  NodeKind nodeKind(int node) const { return nodeKinds_[node]; }
  bool isVertex(int node) const { return nodeKind(node) == NodeKind::Vertex; }
  /// The elements that contain `node`, with the node's local index in each.
  ConstRange<NodeIncidence> incidentElements(int node) const;

  // --- edges --------------------------------------------------------------
  const Edge& edge(int i) const { return edges_[i]; }
  const std::vector<Edge>& edges() const { return edges_; }
  /// Index of local edge k (0..2) of element e.
  int elementEdge(int e, int k) const { return elementEdges_[e][k]; }
  /// The element across local edge k of element e.
  int neighbour(int e, int k) const;
  /// The edge whose midside node is `node` (-1 if `node` is a vertex).
  int edgeOfMidNode(int node) const { return edgeOfMidNode_[node]; }
  /// The edge joining vertices a and b (either order), or -1 if there is none.
  int findEdge(int a, int b) const;

private:
  void buildIncidence();
  void buildEdges();

  std::vector<double> positions_;
  std::vector<ElementConnectivity> elements_;
  std::vector<NodeKind> nodeKinds_;
  int numVertexNodes_ = 0;
  std::vector<int> incidenceOffsets_; // CSR over nodes
  std::vector<NodeIncidence> incidences_;
  std::vector<Edge> edges_;
  std::vector<std::array<int, 3>> elementEdges_;
  std::vector<int> edgeOfMidNode_;
  std::unordered_map<std::uint64_t, int> edgeByVertices_;
};

/// Local vertex indices (a, b) and midside local node of local edge k (0..2).
inline std::array<int, 3> localEdgeNodes(int k)
{
  switch (k) {
  case 0:
    return {0, 1, 3};
  case 1:
    return {1, 2, 4};
  default:
    return {2, 0, 5};
  }
}

} // namespace capsula::mesh
