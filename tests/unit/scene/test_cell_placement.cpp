#include <capsula/core/Error.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/scene/CellPlacement.hpp>

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

TEST(CellPlacement, DetectsOverlappingCells)
{
  const auto a = sphereAt(0, 3, 0);
  const auto apart = sphereAt(2.05, 3, 0);
  const auto overlapping = sphereAt(1.8, 3, 0);
  const auto inside = sphereAt(0.1, 3, 0, 0.3);   // wholly inside a: no surface crossing
  EXPECT_FALSE(scene::surfacesOverlap(a, apart));
  EXPECT_TRUE(scene::surfacesOverlap(a, overlapping));
  EXPECT_TRUE(scene::surfacesOverlap(a, inside));
  EXPECT_TRUE(scene::surfacesOverlap(inside, a));
  EXPECT_NO_THROW(scene::requireNoOverlap({&a, &apart}, {"Cells/Cell 0", "Cells/Cell 1"}));
  try {
    scene::requireNoOverlap({&a, &apart, &overlapping}, {"Cells/Cell 0", "Cells/Cell 1", "Cells/Cell 2"});
    FAIL() << "cells 0 and 2 overlap";
  } catch (const capsula::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Cells/Cell 0' and 'Cells/Cell 2' overlap"),
              std::string::npos)
      << e.what();
  }
}

} // namespace
