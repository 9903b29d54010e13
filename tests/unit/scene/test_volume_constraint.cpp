// VolumeConstraint ('Cells/Cell k/Conserve volume'): what it removes and what it leaves.
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/NodeNormals.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/scene/VolumeConstraint.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using capsula::mesh::SurfaceMesh;
using capsula::mesh::Vec3;
using capsula::scene::normalFlux;
using capsula::scene::VolumeConstraint;

// An ellipsoid with its centre off the origin: no symmetry of the mesh helps the flux vanish.
SurfaceMesh ellipsoid()
{
  capsula::mesh::Placement placement;
  placement.centre = Vec3(0.3, 1.7, -0.2);
  return capsula::mesh::makeEllipsoid(2, Vec3(1.3, 0.8, 0.9), placement);
}

template <typename Field>
std::vector<double> sample(const SurfaceMesh& mesh, Field&& field)
{
  std::vector<double> values(3 * static_cast<std::size_t>(mesh.numNodes()));
  for (int i = 0; i < mesh.numNodes(); ++i) {
    const Vec3 v = field(mesh.position(i));
    for (int d = 0; d < 3; ++d) {
      values[3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(d)] = v[d];
    }
  }
  return values;
}

// The flux of the position field x is 3 V (the divergence theorem): normalFlux against the
// mesh's own volume integral, to round-off (the same rule integrates the same polynomial);
// a uniform field carries none to the rule's accuracy.
TEST(VolumeConstraint, NormalFluxMeasuresTheVolumeRate)
{
  const SurfaceMesh mesh = ellipsoid();
  const double volume = capsula::mesh::enclosedVolume(mesh, 12);
  EXPECT_NEAR(normalFlux(mesh, mesh.positionData()), 3.0 * volume, 1e-12 * volume);
  const std::vector<double> uniform = sample(mesh, [](const Vec3&) -> Vec3 { return Vec3(0.4, -1.1, 0.7); });
  EXPECT_NEAR(normalFlux(mesh, uniform.data()), 0.0, 1e-5); // measured 1e-8 to 1e-7 at level 2
}

// A normal inflation (0.05 n_k at every node) is removed, and a rigid motion passes
// unchanged: the sum of the two comes out as the rigid motion alone, with no net flux left.
TEST(VolumeConstraint, RemovesTheNetFluxAndKeepsRigidMotions)
{
  SurfaceMesh mesh = ellipsoid();
  const Vec3 centre(0.3, 1.7, -0.2);
  const auto rigid = [&](const Vec3& x) -> Vec3 {
    return Vec3(1.7, 0.2, 0.1) + Vec3(0.3, -0.5, 0.8).cross(x - centre);
  };
  const std::vector<Vec3> normals = capsula::mesh::nodeNormals(mesh);
  std::vector<double> u = sample(mesh, rigid);
  for (std::size_t i = 0; i < normals.size(); ++i) {
    for (int d = 0; d < 3; ++d) {
      u[3 * i + static_cast<std::size_t>(d)] += 0.05 * normals[i][d];
    }
  }
  // The state: 2 nodes of another cell before this one, which the constraint must not touch.
  const std::size_t offset = 2;
  std::vector<double> positions(3 * offset, 0.0);
  positions.insert(positions.end(), mesh.positions().begin(), mesh.positions().end());
  std::vector<double> velocities(3 * offset, 9.0);
  velocities.insert(velocities.end(), u.begin(), u.end());

  VolumeConstraint constraint({mesh}, {static_cast<int>(offset)});
  constraint.apply(positions, velocities);
  for (std::size_t i = 0; i < 3 * offset; ++i) {
    EXPECT_EQ(velocities[i], 9.0); // the other nodes are not touched
  }
  EXPECT_NEAR(normalFlux(mesh, velocities.data() + 3 * offset), 0.0, 1e-12);
  // Left: the rigid motion, less c n_k for the rule's error on its flux (~1e-7).
  const std::vector<double> expected = sample(mesh, rigid);
  double largest = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    largest = std::max(largest, std::abs(velocities[3 * offset + i] - expected[i]));
  }
  EXPECT_LT(largest, 1e-5); // an inflation left in would be 0.05

  // A tangential field (n_k x e_z) carries no net flux to the rule's accuracy either.
  std::vector<double> tangential(3 * offset, 0.0);
  for (const Vec3& n : normals) {
    const Vec3 t = n.cross(Vec3::UnitZ());
    tangential.insert(tangential.end(), {t[0], t[1], t[2]});
  }
  const std::vector<double> before = tangential;
  constraint.apply(positions, tangential);
  double moved = 0.0;
  for (std::size_t i = 0; i < tangential.size(); ++i) {
    moved = std::max(moved, std::abs(tangential[i] - before[i]));
  }
  EXPECT_LT(moved, 1e-5);
}

// On a sphere the expansion is along the node normals, so it is removed to the accuracy of
// those normals.
TEST(VolumeConstraint, RemovesAnExpansionOfASphereCompletely)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  std::vector<double> velocities = sample(mesh, [](const Vec3& x) -> Vec3 { return 0.3 * x; });
  VolumeConstraint constraint({mesh}, {0});
  constraint.apply(mesh.positions(), velocities);
  double largest = 0.0;
  for (const double v : velocities) {
    largest = std::max(largest, std::abs(v));
  }
  // What is left is 0.3 (x/|x| - c n_k): the level-2 node normals (area-averaged over the
  // quadratic elements) are off the radial direction by ~5e-4 (measured 1.4e-4 of 0.3).
  EXPECT_LT(largest, 0.3 * 1e-3);
}

} // namespace
