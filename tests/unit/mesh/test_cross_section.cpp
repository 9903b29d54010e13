// Plane cuts of the surface (cell profiles).
#include "capsula/testing/Constants.hpp"
#include <capsula/mesh/CrossSection.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using capsula::testing::pi;

using namespace capsula::mesh;

namespace {

/// Signed area of a closed planar polyline about `normal` (shoelace in 3D).
double signedArea(const Polyline& line, const Vec3& normal)
{
  Vec3 twice = Vec3::Zero();
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    twice += line.points[i].cross(line.points[(i + 1) % line.points.size()]);
  }
  return 0.5 * twice.dot(normal);
}

} // namespace

TEST(MeshCrossSection, SphereCutIsACircle)
{
  const SurfaceMesh sphere = makeSphere(3, 1.0, Placement{Vec3(1.0, 2.0, 3.0), Mat3::Identity()});
  const double z0 = 3.3;
  const auto pieces = crossSection(sphere, Vec3(0.0, 0.0, z0), Vec3::UnitZ());
  ASSERT_EQ(pieces.size(), 1u);
  const Polyline& circle = pieces.front();
  EXPECT_TRUE(circle.closed);
  const double r = std::sqrt(1.0 - 0.3 * 0.3);
  double worst = 0.0;
  for (const Vec3& p : circle.points) {
    EXPECT_NEAR(p[2], z0, 1e-14); // linear interpolation lands exactly in the plane
    worst = std::max(worst, std::abs((p - Vec3(1.0, 2.0, z0)).norm() - r));
  }
  // Level 3, 8 subdivisions: measured 5.3e-5; the error is O((h/k)^2) from the linear cut
  // plus the O(h^3) surface error.
  EXPECT_LT(worst, 1e-4);
  EXPECT_NEAR(signedArea(circle, Vec3::UnitZ()) / (pi * r * r), 1.0, 1e-3); // counter-clockwise
  // Refining the sub-triangles reduces the error about 4-fold per halving.
  const auto coarse = crossSection(sphere, Vec3(0.0, 0.0, z0), Vec3::UnitZ(), 2);
  double worstCoarse = 0.0;
  for (const Vec3& p : coarse.front().points) {
    worstCoarse = std::max(worstCoarse, std::abs((p - Vec3(1.0, 2.0, z0)).norm() - r));
  }
  EXPECT_GT(worstCoarse, 4.0 * worst);
}

TEST(MeshCrossSection, PlaneThroughMeshVerticesAndPlaneMissingTheSurface)
{
  // z = 0 passes exactly through icosahedron vertices: samples on the plane count as
  // above it, and the cut stays one closed loop without repeated points.
  const SurfaceMesh sphere = makeSphere(2, 1.0);
  const auto pieces = crossSection(sphere, Vec3::Zero(), Vec3::UnitZ(), 4);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_TRUE(pieces.front().closed);
  const auto& pts = pieces.front().points;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    // Neighbouring points are ~h/4 apart; a repeated vertex would show as ~1e-16.
    EXPECT_GT((pts[i] - pts[(i + 1) % pts.size()]).norm(), 1e-6);
  }
  EXPECT_TRUE(crossSection(sphere, Vec3(0.0, 0.0, 1.5), Vec3::UnitZ()).empty());
}

TEST(MeshCrossSection, RedCellProfileFollowsEvansFung)
{
  // The cut through the axis (plane y = 0) is the biconcave profile, one closed loop.
  const BiconcaveProfile shape; // R0 = 1
  const SurfaceMesh cell = makeBiconcaveCell(3, shape);
  const auto pieces = crossSection(cell, Vec3::Zero(), Vec3::UnitY());
  ASSERT_EQ(pieces.size(), 1u);
  double worst = 0.0;
  for (const Vec3& p : pieces.front().points) {
    const double s = std::min(p[0] * p[0], 1.0);
    const double half = 0.5 * std::sqrt(1.0 - s) * (shape.c0 + shape.c1 * s + shape.c2 * s * s);
    // Compare away from the rim, where z(r) is steep and a vertical distance means little.
    if (s < 0.9)
      worst = std::max(worst, std::abs(std::abs(p[2]) - half));
  }
  EXPECT_LT(worst, 1e-3); // measured 3.3e-4 at level 3 (rim radius of curvature 0.3 R0)
  std::printf("  biconcave profile: %zu points, worst |z| error %.3e\n", pieces.front().points.size(), worst);
}
