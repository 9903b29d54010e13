#include <capsula/mesh/SurfaceMesh.hpp>
#include "EdgeKey.hpp"
#include <capsula/core/Error.hpp>

#include <algorithm>
#include <utility>

namespace capsula::mesh {

using core::InputError;
using core::require;

namespace {

constexpr std::uint8_t unassigned = 255;

} // namespace

SurfaceMesh::SurfaceMesh(std::vector<double> positions, std::vector<ElementConnectivity> elements)
    : positions_(std::move(positions)), elements_(std::move(elements))
{
  require<InputError>(positions_.size() % 3 == 0, "SurfaceMesh: the position array holds ", positions_.size(),
                      " values; it must hold 3 per node");
  require<InputError>(!elements_.empty(), "SurfaceMesh: the element list is empty");
  const int n = numNodes();

  // Node kinds: a node listed as local 0..2 is a vertex, as 3..5 a midside node.
  std::vector<std::uint8_t> kind(n, unassigned);
  for (int e = 0; e < numElements(); ++e) {
    for (int i = 0; i < 6; ++i) {
      const int node = elements_[e][i];
      require<InputError>(node >= 0 && node < n, "SurfaceMesh: element ", e, " lists node ", node, ", outside 0..",
                          n - 1);
      const std::uint8_t k = i < 3 ? 0 : 1;
      auto& slot = kind[node];
      require<InputError>(slot == unassigned || slot == k, "SurfaceMesh: node ", node,
                          " is a vertex of one element and a midside node of another");
      slot = k;
    }
  }
  nodeKinds_.resize(n);
  for (int node = 0; node < n; ++node) {
    const auto k = kind[node];
    require<InputError>(k != unassigned, "SurfaceMesh: node ", node, " belongs to no element");
    nodeKinds_[node] = k == 0 ? NodeKind::Vertex : NodeKind::Edge;
    numVertexNodes_ += k == 0 ? 1 : 0;
  }

  buildIncidence();
  buildEdges();
}

void SurfaceMesh::buildIncidence()
{
  const int n = numNodes();
  incidenceOffsets_.assign(n + 1, 0);
  for (const auto& el : elements_) {
    for (int node : el) {
      ++incidenceOffsets_[node + 1];
    }
  }
  for (int i = 0; i < n; ++i) {
    incidenceOffsets_[i + 1] += incidenceOffsets_[i];
  }
  incidences_.resize(incidenceOffsets_[n]);
  std::vector<int> fill(incidenceOffsets_.begin(), incidenceOffsets_.end() - 1);
  for (int e = 0; e < numElements(); ++e) {
    for (int i = 0; i < 6; ++i) {
      incidences_[fill[elements_[e][i]]++] = {e, i};
    }
  }
}

void SurfaceMesh::buildEdges()
{
  elementEdges_.assign(elements_.size(), {-1, -1, -1});
  edgeOfMidNode_.assign(numNodes(), -1);
  edges_.reserve(elements_.size() * 3 / 2);
  edgeByVertices_.reserve(elements_.size() * 3 / 2);

  for (int e = 0; e < numElements(); ++e) {
    const auto& el = elements_[e];
    for (int k = 0; k < 3; ++k) {
      const auto local = localEdgeNodes(k);
      const int a = el[local[0]];
      const int b = el[local[1]];
      const int mid = el[local[2]];
      require<InputError>(a != b, "SurfaceMesh: element ", e, " repeats vertex ", a);
      const auto [it, inserted] = edgeByVertices_.try_emplace(detail::edgeKey(a, b), numEdges());
      if (inserted) {
        edges_.push_back({{a, b}, mid, {e, -1}, {k, -1}});
      } else {
        Edge& edge = edges_[it->second];
        require<InputError>(edge.elements[1] < 0, "SurfaceMesh: edge ", a, "-", b,
                            " is shared by more than two elements (not a 2-manifold)");
        require<InputError>(edge.midNode == mid, "SurfaceMesh: edge ", a, "-", b, " has two different midside nodes, ",
                            edge.midNode, " and ", mid);
        require<InputError>(edge.vertices[0] == b && edge.vertices[1] == a, "SurfaceMesh: elements ", edge.elements[0],
                            " and ", e, " traverse edge ", a, "-", b,
                            " in the same direction (inconsistent orientation)");
        edge.elements[1] = e;
        edge.localEdges[1] = k;
      }
      elementEdges_[e][k] = it->second;
      edgeOfMidNode_[mid] = it->second;
    }
  }
  for (const Edge& edge : edges_) {
    require<InputError>(edge.elements[1] >= 0, "SurfaceMesh: edge ", edge.vertices[0], "-", edge.vertices[1],
                        " belongs to one element only (the surface is not closed)");
  }
}

void SurfaceMesh::setPositions(const std::vector<double>& positions)
{
  require<InputError>(positions.size() == positions_.size(), "SurfaceMesh::setPositions: got ", positions.size(),
                      " values for ", numNodes(), " nodes; expected ", positions_.size());
  positions_ = positions;
}

void SurfaceMesh::setPositions(const double* positions)
{
  std::copy(positions, positions + positions_.size(), positions_.begin());
}

void SurfaceMesh::setPosition(int node, const Vec3& x)
{
  double* p = positions_.data() + 3 * node;
  p[0] = x[0];
  p[1] = x[1];
  p[2] = x[2];
}

ConstRange<NodeIncidence> SurfaceMesh::incidentElements(int node) const
{
  return {incidences_.data() + incidenceOffsets_[node], incidences_.data() + incidenceOffsets_[node + 1]};
}

int SurfaceMesh::neighbour(int e, int k) const
{
  const Edge& edge = edges_[elementEdge(e, k)];
  return edge.elements[0] == e ? edge.elements[1] : edge.elements[0];
}

int SurfaceMesh::findEdge(int a, int b) const
{
  const auto it = edgeByVertices_.find(detail::edgeKey(a, b));
  return it == edgeByVertices_.end() ? -1 : it->second;
}

} // namespace capsula::mesh
