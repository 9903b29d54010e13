#pragma once
// Neighbourhoods of mesh nodes, the point sets the local surface fits work on.
//
// Every node of the quadratic mesh (vertex or midside) samples the surface, so the
// neighbourhoods are taken in the graph of the linear triangulation through all nodes:
// each 6-node element counts as its four sub-triangles (v0, m01, m20), (m01, v1, m12),
// (m20, m12, v2), (m01, m12, m20). Ring k holds the nodes k edges away in that graph;
// for a vertex, rings 1..2 are exactly the nodes of the elements around it.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::mesh {

/// Node-to-node adjacency of the sub-triangle graph (compressed rows: the neighbours of
/// node i are nodes[offsets[i] .. offsets[i+1]), sorted).
struct NodeGraph {
  std::vector<int> offsets;
  std::vector<int> nodes;
  ConstRange<int> neighbours(int node) const
  {
    const auto i = static_cast<std::size_t>(node);
    return {nodes.data() + offsets[i], nodes.data() + offsets[i + 1]};
  }
};

NodeGraph nodeGraph(const SurfaceMesh& mesh);

/// The nodes within `rings` (>= 1) edges of `node`, without `node` itself, nearest rings
/// first. `scratch` (numNodes() ints, all -1 on entry and on return) marks visited nodes.
std::vector<int> nodeNeighbourhood(const NodeGraph& graph, int node, int rings, std::vector<int>& scratch);

} // namespace capsula::mesh
