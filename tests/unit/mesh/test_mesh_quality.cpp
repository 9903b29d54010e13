// Element angles, edge ratios and midside-node distortion.
#include <capsula/mesh/Icosphere.hpp>
#include <capsula/mesh/MeshQuality.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

using namespace capsula::mesh;

TEST(MeshQuality, RegularTetrahedronWithShiftedMidsideNodes)
{
  // Four equilateral faces; each midside node at 0.3 of its edge from the lower-numbered
  // vertex, so every element has alpha, beta or gamma = 0.3 or 0.7: distortion 0.2.
  const Vec3 v[4] = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  const int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  std::vector<double> x;
  for (const Vec3& p : v)
    x.insert(x.end(), {p[0], p[1], p[2]});
  for (const auto& e : edges) {
    const Vec3 m = v[e[0]] + 0.3 * (v[e[1]] - v[e[0]]);
    x.insert(x.end(), {m[0], m[1], m[2]});
  }
  const SurfaceMesh tet(x, {{0, 2, 1, 5, 7, 4}, {0, 1, 3, 4, 8, 6}, {0, 3, 2, 6, 9, 5}, {1, 2, 3, 7, 9, 8}});
  for (int e = 0; e < tet.numElements(); ++e) {
    const ElementQuality q = elementQuality(tet, e);
    EXPECT_NEAR(q.minAngle, 60.0, 1e-12);
    EXPECT_NEAR(q.maxAngle, 60.0, 1e-12);
    EXPECT_NEAR(q.edgeRatio, 1.0, 1e-14);
    EXPECT_NEAR(q.distortion, 0.2, 1e-14);
  }
}

TEST(MeshQuality, SquashedOctahedronHasIsoscelesFaces)
{
  // Vertices (+-1,0,0), (0,+-1,0), (0,0,+-h): eight congruent isosceles faces with base
  // sqrt(2) and sides sqrt(1 + h^2), whose angles follow in closed form.
  const double h = 0.5;
  const Vec3 v[6] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, h), Vec3(0, 0, -h)};
  std::vector<double> x;
  for (const Vec3& p : v)
    x.insert(x.end(), {p[0], p[1], p[2]});
  std::vector<ElementConnectivity> elements;
  int next = 6;
  std::map<std::pair<int, int>, int> mids;
  const auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto it = mids.find(key);
    if (it != mids.end())
      return it->second;
    const Vec3 m = 0.5 * (v[a] + v[b]);
    x.insert(x.end(), {m[0], m[1], m[2]});
    mids[key] = next;
    return next++;
  };
  for (int k = 0; k < 4; ++k) {
    const int a = k, b = (k + 1) % 4;
    elements.push_back({a, b, 4, mid(a, b), mid(b, 4), mid(4, a)});
    elements.push_back({b, a, 5, mid(b, a), mid(a, 5), mid(5, b)});
  }
  const SurfaceMesh octahedron(x, elements);
  const double side = std::sqrt(1.0 + h * h), base = std::sqrt(2.0);
  const double apex = 2.0 * std::asin(0.5 * base / side) * 180.0 / std::acos(-1.0);
  const double baseAngle = 0.5 * (180.0 - apex);
  const MeshQuality q = meshQuality(octahedron);
  EXPECT_NEAR(q.minAngle, std::min(apex, baseAngle), 1e-12);
  EXPECT_NEAR(q.maxAngle, std::max(apex, baseAngle), 1e-12);
  EXPECT_NEAR(q.maxEdgeRatio, base / side, 1e-14);
  EXPECT_NEAR(q.maxDistortion, 0.0, 1e-14);
}

TEST(MeshQuality, IcosphereStaysNearlyEquilateral)
{
  std::printf("  level  min angle  max angle  max edge ratio   (icosphere)\n");
  for (int level = 0; level <= 4; ++level) {
    const MeshQuality q = meshQuality(makeIcosphere(level));
    std::printf("  %5d  %9.3f  %9.3f  %14.4f\n", level, q.minAngle, q.maxAngle, q.maxEdgeRatio);
    // Projecting at every level keeps the angles within [54, 72] degrees (the limit is
    // 54.0 / 72.0 as level grows; measured 54.02 at level 4).
    EXPECT_GT(q.minAngle, 54.0);
    EXPECT_LT(q.maxAngle, 72.0);
    EXPECT_LT(q.maxEdgeRatio, 1.18);
    // Midside nodes are projected edge midpoints: symmetric about the edge, alpha = 1/2.
    EXPECT_LT(q.maxDistortion, 1e-13);
  }
  // The biconcave map places midside nodes unevenly: distortion becomes visible.
  const MeshQuality rbc = meshQuality(makeBiconcaveCell(2));
  std::printf("  biconcave level 2: min angle %.2f, max edge ratio %.3f, distortion %.4f\n", rbc.minAngle,
              rbc.maxEdgeRatio, rbc.maxDistortion);
  EXPECT_GT(rbc.maxDistortion, 1e-3);
}
