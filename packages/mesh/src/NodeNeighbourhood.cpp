#include <capsula/mesh/NodeNeighbourhood.hpp>

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <array>
#include <utility>

namespace capsula::mesh {

NodeGraph nodeGraph(const SurfaceMesh& mesh)
{
  // The nine sub-triangle edges of an element, as local node pairs: the two halves of
  // each element edge and the three edges joining the midside nodes.
  static constexpr std::array<std::array<int, 2>, 9> subEdges{
      {{0, 3}, {3, 1}, {1, 4}, {4, 2}, {2, 5}, {5, 0}, {3, 4}, {4, 5}, {5, 3}}};
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(static_cast<std::size_t>(mesh.numElements()) * 18);
  for (const ElementConnectivity& el : mesh.elements()) {
    for (const auto& e : subEdges) {
      const int a = el[static_cast<std::size_t>(e[0])];
      const int b = el[static_cast<std::size_t>(e[1])];
      pairs.emplace_back(a, b);
      pairs.emplace_back(b, a);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  NodeGraph graph;
  graph.offsets.assign(static_cast<std::size_t>(mesh.numNodes()) + 1, 0);
  graph.nodes.reserve(pairs.size());
  for (const auto& [a, b] : pairs) {
    ++graph.offsets[static_cast<std::size_t>(a) + 1];
    graph.nodes.push_back(b);
  }
  for (std::size_t i = 1; i < graph.offsets.size(); ++i) {
    graph.offsets[i] += graph.offsets[i - 1];
  }
  return graph;
}

std::vector<int> nodeNeighbourhood(const NodeGraph& graph, int node, int rings, std::vector<int>& scratch)
{
  core::require<core::InputError>(rings >= 1, "nodeNeighbourhood: rings = ", rings, " must be at least 1");
  // Breadth-first search; scratch[n] = ring of n while the search runs.
  std::vector<int> found;
  scratch[static_cast<std::size_t>(node)] = 0;
  std::size_t ringBegin = 0;
  found.push_back(node);
  for (int ring = 1; ring <= rings; ++ring) {
    const std::size_t ringEnd = found.size();
    for (std::size_t i = ringBegin; i < ringEnd; ++i) {
      for (int next : graph.neighbours(found[i])) {
        if (scratch[static_cast<std::size_t>(next)] < 0) {
          scratch[static_cast<std::size_t>(next)] = ring;
          found.push_back(next);
        }
      }
    }
    ringBegin = ringEnd;
  }
  for (int n : found) {
    scratch[static_cast<std::size_t>(n)] = -1;
  }
  found.erase(found.begin());
  return found;
}

} // namespace capsula::mesh
