#include <capsula/core/Error.hpp>
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/scene/CellPlacement.hpp>
#include <capsula/scene/SurfaceGap.hpp>

#include <gtest/gtest.h>

namespace {

namespace mesh = capsula::mesh;
namespace scene = capsula::scene;
namespace domain = capsula::domain;

const domain::Domain aboveWall = domain::Domain::aboveWall();

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
  EXPECT_NO_THROW(scene::requireInFluid(sphereAt(0, 1.2, 0), "Cells/Cell 0", aboveWall));
  try {
    scene::requireInFluid(sphereAt(0, 0.9, 0), "Cells/Cell 0", aboveWall);
    FAIL() << "a sphere of radius 1 at height 0.9 crosses the wall";
  } catch (const capsula::core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'Cells/Cell 0' crosses the wall"), std::string::npos) << what;
    EXPECT_NE(what.find("Center"), std::string::npos) << what;
  }
  // Touching (lowest node exactly at y = 0) is not in the fluid either.
  EXPECT_THROW(scene::requireInFluid(sphereAt(0, 1.0, 0), "Cells/Cell 1", aboveWall), capsula::core::InputError);
}

// 'Wall/Minimum gap' at the start: a lowest node at y = gap is refused, one just above is
// accepted; the rise asked for is positive even for a cell touching the wall (it read
// "by more than -0").
TEST(CellPlacement, WallGapAtTheStart)
{
  const auto messageFor = [](double height, double gap) -> std::string {
    try {
      scene::requireWallGaps(sphereAt(0, height, 0), "Cells/Cell 0", aboveWall, gap);
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

// The message of the core::InputError `check` throws, or "accepted".
template <typename Check>
std::string refusal(Check&& check)
{
  try {
    check();
  } catch (const capsula::core::InputError& e) {
    return e.what();
  }
  return "accepted";
}

// In a channel 0 < y < 4 the upper wall is checked like the lower one: a unit sphere at
// height 2.9 has its top pole 0.1 below the upper wall (accepted with a gap of 0.05,
// refused with 0.2, naming the upper wall and both keys), at 3.1 it crosses it.
TEST(CellPlacement, UpperWallOfAChannel)
{
  const auto channel = domain::Domain::channel(4.0);
  EXPECT_EQ(refusal([&] { scene::requireWallGaps(sphereAt(0, 2.9, 0), "Cells/Cell 0", channel, 0.05); }), "accepted");
  const std::string close = refusal([&] { scene::requireWallGaps(sphereAt(0, 2.9, 0), "Cells/Cell 0", channel, 0.2); });
  EXPECT_NE(close.find("'Cells/Cell 0' starts too close to the upper wall: its highest node"), std::string::npos)
      << close;
  EXPECT_NE(close.find("'Wall/Minimum gap' = 0.2"), std::string::npos) << close;
  EXPECT_NE(close.find("Lower the y component"), std::string::npos) << close;
  EXPECT_NE(close.find("raise 'Wall/Channel height'"), std::string::npos) << close;
  const std::string through = refusal([&] { scene::requireInFluid(sphereAt(0, 3.1, 0), "Cells/Cell 2", channel); });
  EXPECT_NE(through.find("'Cells/Cell 2' crosses the upper wall: its highest node"), std::string::npos) << through;
  EXPECT_NE(through.find("by more than 0.1"), std::string::npos) << through;
  // The lower wall of the channel is still checked.
  EXPECT_NE(
      refusal([&] { scene::requireInFluid(sphereAt(0, 0.9, 0), "Cells/Cell 0", channel); }).find("crosses the wall"),
      std::string::npos);
  EXPECT_EQ(refusal([&] { scene::requireInFluid(sphereAt(0, 2.0, 0), "Cells/Cell 0", channel); }), "accepted");
}

// A channel no taller than the cell plus 'Wall/Minimum gap' on each side is refused naming
// 'Wall/Channel height', whatever the cell's height in it: the unit sphere is 2 tall, so
// H = 2.1 fits gaps of 0.025 (2.05 < 2.1) but not of 0.06 (2.12).
TEST(CellPlacement, ChannelNoTallerThanTheCell)
{
  const auto sphere = sphereAt(0, 1.05, 0);
  EXPECT_EQ(
      refusal([&] { scene::requireRoomInDomain(sphere, "Cells/Cell 0", domain::Domain::channel(2.1), 0.025, 0.05); }),
      "accepted");
  const std::string tight =
      refusal([&] { scene::requireRoomInDomain(sphere, "Cells/Cell 0", domain::Domain::channel(2.1), 0.06, 0.05); });
  EXPECT_NE(tight.find("'Wall/Channel height' = 2.1 leaves no room for 'Cells/Cell 0', which is 2 tall"),
            std::string::npos)
      << tight;
}

// A period no longer than the cell plus 'Cells/Minimum gap' makes the cell overlap (or touch)
// its own image: refused naming the key of that direction.
TEST(CellPlacement, CellOverlappingItsOwnPeriodicImage)
{
  const auto sphere = sphereAt(0.3, 2.0, -0.7);
  domain::DomainShape shape;
  shape.periodX = 2.04;
  shape.periodZ = 5.0;
  const std::string shortX =
      refusal([&] { scene::requireRoomInDomain(sphere, "Cells/Cell 3", domain::Domain(shape), 0.025, 0.05); });
  EXPECT_NE(shortX.find("'Domain/Periodic length x' = 2.04 is too short for 'Cells/Cell 3', which is 2 long along x"),
            std::string::npos)
      << shortX;
  EXPECT_NE(shortX.find("its own periodic image"), std::string::npos) << shortX;
  shape.periodX = 2.06;
  EXPECT_EQ(refusal([&] { scene::requireRoomInDomain(sphere, "Cells/Cell 3", domain::Domain(shape), 0.025, 0.05); }),
            "accepted");
  shape.periodZ = 1.9;
  EXPECT_NE(refusal([&] {
              scene::requireRoomInDomain(sphere, "Cells/Cell 3", domain::Domain(shape), 0.025, 0.05);
            }).find("'Domain/Periodic length z' = 1.9"),
            std::string::npos);
}

// Two cells far apart inside the box can touch across the periodic boundary: with L_x = 6,
// unit spheres at x = 0.5 and x = 4.47 are 3.97 apart directly but 2.03 through the boundary
// (a gap of about 0.03 between the surfaces, under 'Cells/Minimum gap' = 0.05), and overlap
// there when the second is moved to 4.8 (1.7 apart).
TEST(CellPlacement, CellsTouchingAcrossThePeriodicBoundary)
{
  domain::DomainShape shape;
  shape.periodX = 6.0;
  const domain::Domain box(shape);
  const auto first = sphereAt(0.5, 2.0, 0.0);
  const auto touching = sphereAt(4.47, 2.0, 0.0);
  const auto overlapping = sphereAt(4.8, 2.0, 0.0);
  const auto apart = sphereAt(3.5, 2.0, 0.0);
  const std::vector<std::string> paths{"Cells/Cell 0", "Cells/Cell 1"};
  // Unbounded, both pairs are far apart.
  EXPECT_EQ(refusal([&] { scene::requireNoOverlap({&first, &touching}, paths, 0.05); }), "accepted");
  EXPECT_EQ(refusal([&] { scene::requireNoOverlap({&first, &overlapping}, paths, 0.05); }), "accepted");
  const std::string touch = refusal([&] { scene::requireNoOverlap({&first, &touching}, paths, 0.05, box); });
  EXPECT_NE(touch.find("touch at the start"), std::string::npos) << touch;
  EXPECT_NE(touch.find("across the periodic boundary"), std::string::npos) << touch;
  const std::string overlap = refusal([&] { scene::requireNoOverlap({&first, &overlapping}, paths, 0.05, box); });
  EXPECT_NE(overlap.find("overlap at the start"), std::string::npos) << overlap;
  EXPECT_NE(overlap.find("shifted by (-6, 0, 0)"), std::string::npos) << overlap;
  EXPECT_EQ(refusal([&] { scene::requireNoOverlap({&first, &apart}, paths, 0.05, box); }), "accepted");
}

// The gap to the nearest periodic image: unit spheres at x = 1.1 and x = 7.0 in a box of
// L_x = 8 are 5.9 apart directly but 2.1 through the boundary, and their gap is that of the
// same pair with the second sphere placed at x = -1.0 inside the box, to round-off (the
// meshes are the same up to a translation by L_x). The closest point is reported on the
// second sphere itself (near x = 7 - 1), not on its image.
TEST(SurfaceGap, NearestPeriodicImage)
{
  domain::DomainShape shape;
  shape.periodX = 8.0;
  const domain::Domain box(shape);
  const auto first = sphereAt(1.1, 2.0, 0.0);
  const auto across = sphereAt(7.0, 2.0, 0.0);
  const auto inside = sphereAt(-1.0, 2.0, 0.0);
  const auto periodic = scene::minimumSurfaceGap(first, first.positionData(), across, across.positionData(), box);
  const auto direct = scene::minimumSurfaceGap(first, inside);
  EXPECT_NEAR(periodic.distance, direct.distance, 1e-12);
  EXPECT_NEAR(direct.distance, 0.1, 0.01); // 0.1 between the spheres, the facets' sag at level 2
  EXPECT_NEAR(periodic.onSecond[0], direct.onSecond[0] + 8.0, 1e-12);
  // Without the period the same pair is 3.9 apart.
  EXPECT_GT(scene::minimumSurfaceGap(first, across).distance, 3.8);
  const auto unbounded =
      scene::minimumSurfaceGap(first, first.positionData(), across, across.positionData(), domain::Domain::aboveWall());
  EXPECT_EQ(unbounded.distance, scene::minimumSurfaceGap(first, across).distance);
}

} // namespace
