#include <capsula/core/Error.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/scene/CellPlacement.hpp>
#include <capsula/scene/SurfaceGap.hpp>

#include <gtest/gtest.h>

namespace {

namespace mesh = capsula::mesh;
namespace scene = capsula::scene;

mesh::SurfaceMesh sphereAt(double x, double y, double z, double radius = 1.0, int level = 2)
{
  mesh::Placement p;
  p.centre = mesh::Vec3(x, y, z);
  return mesh::makeSphere(level, radius, p);
}

TEST(CellPlacement, WindingNumberIsOneInsideZeroOutside)
{
  const auto cell = sphereAt(0.5, 2.0, -1.0);
  // Exact integers away from the surface: the solid angles of a closed polyhedron sum to
  // 4 pi or 0 up to round-off.
  EXPECT_NEAR(scene::windingNumber(cell, mesh::Vec3(0.5, 2.0, -1.0)), 1.0, 1e-12);
  EXPECT_NEAR(scene::windingNumber(cell, mesh::Vec3(1.2, 2.3, -0.8)), 1.0, 1e-12);
  EXPECT_NEAR(scene::windingNumber(cell, mesh::Vec3(2.0, 2.0, -1.0)), 0.0, 1e-12);
  EXPECT_NEAR(scene::windingNumber(cell, mesh::Vec3(-5.0, 0.0, 3.0)), 0.0, 1e-12);
}

TEST(CellPlacement, RejectsACellThatCrossesTheWall)
{
  EXPECT_NO_THROW(scene::requireAboveWall(sphereAt(0, 1.2, 0), "Cells/Cell 0"));
  try {
    scene::requireAboveWall(sphereAt(0, 0.9, 0), "Cells/Cell 0");
    FAIL() << "a sphere of radius 1 at height 0.9 crosses the wall";
  } catch (const capsula::core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'Cells/Cell 0' crosses the wall"), std::string::npos) << what;
    EXPECT_NE(what.find("Center"), std::string::npos) << what;
  }
  // Touching (lowest node exactly at y = 0) is not in the fluid either.
  EXPECT_THROW(scene::requireAboveWall(sphereAt(0, 1.0, 0), "Cells/Cell 1"), capsula::core::InputError);
}

// 'Wall/Minimum gap' at the start: a lowest node at y = gap is refused, one just above is
// accepted; the rise asked for is positive even for a cell touching the wall (it read
// "by more than -0").
TEST(CellPlacement, WallGapAtTheStart)
{
  const auto messageFor = [](double height, double gap) -> std::string {
    try {
      scene::requireWallGap(sphereAt(0, height, 0), "Cells/Cell 0", gap);
    } catch (const capsula::core::InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  // The level-2 icosphere has a node at the bottom pole, y = height - 1 exactly.
  EXPECT_EQ(messageFor(1.0 + 0.025 + 1e-9, 0.025), "accepted");
  EXPECT_NE(messageFor(1.02, 0.025).find("starts too close to the wall: its lowest node ("), std::string::npos);
  EXPECT_NE(messageFor(1.02, 0.025).find("by more than 0.005,"), std::string::npos) << messageFor(1.02, 0.025);
  EXPECT_NE(messageFor(1.0, 0.025).find("touches the wall"), std::string::npos) << messageFor(1.0, 0.025);
  EXPECT_NE(messageFor(1.0, 0.025).find("by more than 0.025,"), std::string::npos) << messageFor(1.0, 0.025);
  EXPECT_NE(messageFor(0.9, 0.0).find("crosses the wall"), std::string::npos) << messageFor(0.9, 0.0);
  EXPECT_EQ(messageFor(1.001, 0.0), "accepted");
}

TEST(CellPlacement, DetectsOverlappingCells)
{
  const auto a = sphereAt(0, 3, 0);
  const auto apart = sphereAt(2.05, 3, 0);
  const auto overlapping = sphereAt(1.8, 3, 0);
  const auto inside = sphereAt(0.1, 3, 0, 0.3); // wholly inside a: no surface crossing
  EXPECT_FALSE(scene::surfacesOverlap(a, apart));
  EXPECT_TRUE(scene::surfacesOverlap(a, overlapping));
  EXPECT_TRUE(scene::surfacesOverlap(a, inside));
  EXPECT_TRUE(scene::surfacesOverlap(inside, a));
  EXPECT_NO_THROW(scene::requireNoOverlap({&a, &apart}, {"Cells/Cell 0", "Cells/Cell 1"}));
  try {
    scene::requireNoOverlap({&a, &apart, &overlapping}, {"Cells/Cell 0", "Cells/Cell 1", "Cells/Cell 2"});
    FAIL() << "cells 0 and 2 overlap";
  } catch (const capsula::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Cells/Cell 0' and 'Cells/Cell 2' overlap"), std::string::npos) << e.what();
  }
}

TEST(SurfaceGap, ClosestPointOnATriangleInEveryRegion)
{
  const mesh::Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  // Exact in floating point: every answer is a short sum of small binary fractions.
  EXPECT_EQ(scene::closestPointOnTriangle({0.5, 0.5, 3}, a, b, c), mesh::Vec3(0.5, 0.5, 0)); // face
  EXPECT_EQ(scene::closestPointOnTriangle({-1, -1, 1}, a, b, c), a);                         // vertex
  EXPECT_EQ(scene::closestPointOnTriangle({3, -1, 0}, a, b, c), b);
  EXPECT_EQ(scene::closestPointOnTriangle({-1, 3, 0}, a, b, c), c);
  EXPECT_EQ(scene::closestPointOnTriangle({1, -2, 0}, a, b, c), mesh::Vec3(1, 0, 0)); // edge ab
  EXPECT_EQ(scene::closestPointOnTriangle({-2, 1, 0}, a, b, c), mesh::Vec3(0, 1, 0)); // edge ca
  EXPECT_EQ(scene::closestPointOnTriangle({2, 2, 0}, a, b, c), mesh::Vec3(1, 1, 0));  // edge bc
  // A degenerate (collinear) triangle is its longest edge.
  EXPECT_EQ(scene::closestPointOnTriangle({1, 1, 0}, a, b, mesh::Vec3(1, 0, 0)), mesh::Vec3(1, 0, 0));
}

TEST(SurfaceGap, GapBetweenTwoSpheres)
{
  const auto a = sphereAt(0, 3, 0);
  // Along x the icosphere has nodes on the axis (midpoints of icosahedron edges), facing
  // each other: the gap of the discrete surfaces is the spheres' gap up to round-off.
  const auto gap = scene::minimumSurfaceGap(a, sphereAt(2.3, 3, 0));
  EXPECT_NEAR(gap.distance, 0.3, 1e-12);
  EXPECT_NEAR(gap.onFirst[0], 1.0, 1e-12);
  EXPECT_NEAR(gap.onSecond[0], 1.3, 1e-12);
  // In a general direction the flat facets lie inside the spheres by at most their chord
  // sag, kappa l^2 / 8 with facets of side l ~ 0.33 at level 2: ~0.014 per sphere.
  const mesh::Vec3 direction = mesh::Vec3(0.3, 0.5, 0.8).normalized();
  const mesh::Vec3 centre = mesh::Vec3(0, 3, 0) + 2.3 * direction;
  const auto oblique = scene::minimumSurfaceGap(a, sphereAt(centre[0], centre[1], centre[2]));
  EXPECT_GE(oblique.distance, 0.3 - 1e-12);
  EXPECT_LE(oblique.distance, 0.3 + 2 * 0.014);
  // Symmetric in its arguments.
  EXPECT_DOUBLE_EQ(scene::minimumSurfaceGap(sphereAt(centre[0], centre[1], centre[2]), a).distance, oblique.distance);
}

TEST(CellPlacement, RejectsTouchingCells)
{
  const auto a = sphereAt(0, 3, 0);
  const auto touching = sphereAt(2.0, 3, 0); // node (1, 3, 0) of each coincides
  const auto near = sphereAt(2.03, 3, 0);
  const auto apart = sphereAt(2.5, 3, 0);
  EXPECT_FALSE(scene::surfacesOverlap(a, touching)); // not overlapping, but touching:
  try {
    scene::requireNoOverlap({&a, &touching}, {"Cells/Cell 0", "Cells/Cell 1"});
    FAIL() << "touching cells must be rejected even with no minimum gap";
  } catch (const capsula::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Cells/Cell 0' and 'Cells/Cell 1' touch at the start"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(scene::requireNoOverlap({&a, &near}, {"Cells/Cell 0", "Cells/Cell 1"}));
  EXPECT_THROW(scene::requireNoOverlap({&a, &near}, {"Cells/Cell 0", "Cells/Cell 1"}, 0.05), capsula::core::InputError);
  EXPECT_NO_THROW(scene::requireNoOverlap({&a, &apart}, {"Cells/Cell 0", "Cells/Cell 1"}, 0.05));
}

} // namespace
