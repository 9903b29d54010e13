// Topology of the icosphere (thesis Table 3.1) and the checks SurfaceMesh makes on
// any connectivity it is given.
#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Icosphere.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <gtest/gtest.h>

#include <set>
#include <vector>

using namespace capsula::mesh;

TEST(MeshTopology, IcosphereCountsMatchTable31)
{
  const int expectedElements[] = {20, 80, 320, 1280, 5120, 20480};
  for (int level = 0; level <= 5; ++level) {
    const SurfaceMesh mesh = makeIcosphere(level);
    const int ne = expectedElements[level];
    EXPECT_EQ(mesh.numElements(), ne) << "level " << level;
    EXPECT_EQ(mesh.numNodes(), 2 * ne + 2) << "level " << level;
    EXPECT_EQ(mesh.numEdges(), 3 * ne / 2) << "level " << level;
    // Euler characteristic of a sphere, counting the vertex triangulation: V - E + F = 2.
    EXPECT_EQ(mesh.numVertexNodes() - mesh.numEdges() + mesh.numElements(), 2) << "level " << level;
  }
}

TEST(MeshTopology, EveryEdgeHasTwoElementsAndOneMidsideNode)
{
  const SurfaceMesh mesh = makeIcosphere(3);
  std::set<int> midNodes;
  for (int i = 0; i < mesh.numEdges(); ++i) {
    const Edge& edge = mesh.edge(i);
    ASSERT_NE(edge.elements[0], edge.elements[1]);
    for (int side = 0; side < 2; ++side) {
      const int e = edge.elements[side];
      const int k = edge.localEdges[side];
      EXPECT_EQ(mesh.elementEdge(e, k), i);
      const auto local = localEdgeNodes(k);
      const auto& el = mesh.element(e);
      EXPECT_EQ(el[local[2]], edge.midNode);
      // Side 0 traverses the edge as stored, side 1 backwards (consistent orientation).
      const int a = el[local[0]], b = el[local[1]];
      EXPECT_EQ(a, edge.vertices[side]);
      EXPECT_EQ(b, edge.vertices[1 - side]);
    }
    EXPECT_EQ(mesh.neighbour(edge.elements[0], edge.localEdges[0]), edge.elements[1]);
    EXPECT_EQ(mesh.neighbour(edge.elements[1], edge.localEdges[1]), edge.elements[0]);
    EXPECT_EQ(mesh.findEdge(edge.vertices[1], edge.vertices[0]), i);
    EXPECT_EQ(mesh.edgeOfMidNode(edge.midNode), i);
    EXPECT_EQ(mesh.nodeKind(edge.midNode), NodeKind::Edge);
    EXPECT_TRUE(midNodes.insert(edge.midNode).second) << "midside node on two edges";
  }
  EXPECT_EQ(static_cast<int>(midNodes.size()) + mesh.numVertexNodes(), mesh.numNodes());
  EXPECT_EQ(mesh.findEdge(0, 0), -1);
}

TEST(MeshTopology, IncidenceListsEveryElementOfEveryNode)
{
  const SurfaceMesh mesh = makeIcosphere(2);
  std::size_t total = 0;
  for (int node = 0; node < mesh.numNodes(); ++node) {
    for (const NodeIncidence& inc : mesh.incidentElements(node)) {
      EXPECT_EQ(mesh.element(inc.element)[inc.localNode], node);
    }
    const std::size_t count = mesh.incidentElements(node).size();
    // Icosphere: midside nodes have 2 elements, vertices 5 (the 12 original) or 6.
    if (mesh.isVertex(node)) {
      EXPECT_TRUE(count == 5 || count == 6) << "node " << node;
    } else {
      EXPECT_EQ(count, 2u) << "node " << node;
    }
    total += count;
  }
  EXPECT_EQ(total, 6u * static_cast<std::size_t>(mesh.numElements()));
}

TEST(MeshTopology, IcosphereNormalsPointOutwardAtEveryQuadraturePoint)
{
  const auto& rule = capsula::quadrature::triangleRule(13);
  for (int level = 0; level <= 3; ++level) {
    const SurfaceMesh mesh = makeIcosphere(level);
    double worst = 1.0;
    for (int e = 0; e < mesh.numElements(); ++e) {
      const ElementNodes x = mesh.elementNodes(e);
      const ShapeParameters p = shapeParameters(x);
      for (std::size_t q = 0; q < rule.weight.size(); ++q) {
        const SurfacePoint s = evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
        worst = std::min(worst, s.normal.dot(s.position.normalized()));
      }
    }
    // Outward and nearly radial (cosine to the radial direction measured 0.9963 at level
    // 0, 0.99999996 at level 3); a wrongly oriented element would give about -1.
    EXPECT_GT(worst, 0.99) << "level " << level;
  }
}

TEST(MeshTopology, PositionsRoundTripAsOneFlatArray)
{
  SurfaceMesh mesh = makeIcosphere(1);
  std::vector<double> x = mesh.positions();
  ASSERT_EQ(x.size(), 3u * static_cast<std::size_t>(mesh.numNodes()));
  for (double& v : x)
    v *= 2.0;
  mesh.setPositions(x);
  EXPECT_EQ(mesh.positions(), x);
  mesh.setPosition(7, Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(mesh.position(7), Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(mesh.positions()[21], 1.0);
  EXPECT_THROW(mesh.setPositions(std::vector<double>(5, 0.0)), capsula::core::InputError);
  EXPECT_THROW(makeIcosphere(-1), capsula::core::InputError);
}

namespace {

/// A tetrahedron of quadratic triangles: 4 vertices, 6 midside nodes, outward.
std::vector<ElementConnectivity> tetrahedron()
{
  // Vertices 0..3; midside node of edge (a, b) numbered 4 + index in this list.
  // edges: 01 02 03 12 13 23 -> 4 5 6 7 8 9
  return {{0, 2, 1, 5, 7, 4}, {0, 1, 3, 4, 8, 6}, {0, 3, 2, 6, 9, 5}, {1, 2, 3, 7, 9, 8}};
}

} // namespace

TEST(MeshTopology, ConstructorAcceptsAClosedSurfaceAndRejectsBrokenOnes)
{
  const std::vector<double> x(30, 0.0);
  const SurfaceMesh tet(x, tetrahedron());
  EXPECT_EQ(tet.numEdges(), 6);
  EXPECT_EQ(tet.numVertexNodes() - tet.numEdges() + tet.numElements(), 2);

  auto flipped = tetrahedron(); // one element reversed: inconsistent orientation
  flipped[0] = {0, 1, 2, 4, 7, 5};
  EXPECT_THROW(SurfaceMesh(x, flipped), capsula::core::InputError);

  auto open = tetrahedron(); // three elements: the surface has a hole
  open.pop_back();
  EXPECT_THROW(SurfaceMesh(std::vector<double>(30, 0.0), open), capsula::core::InputError);

  auto mixed = tetrahedron(); // node 4 used as a vertex and as a midside node
  mixed[3][0] = 4;
  EXPECT_THROW(SurfaceMesh(x, mixed), capsula::core::InputError);

  EXPECT_THROW(SurfaceMesh(std::vector<double>(29, 0.0), tetrahedron()), capsula::core::InputError);
}
