#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/scene/CellKinematics.hpp>
#include <capsula/scene/FixedHeightConstraint.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

namespace mesh = capsula::mesh;
namespace scene = capsula::scene;
using mesh::Vec3;

mesh::SurfaceMesh tiltedEllipsoid(int level)
{
  mesh::Placement p;
  p.centre = Vec3(0.4, 1.8, -0.3);
  p.rotation = mesh::rotationAboutAxis(Vec3(1.0, 2.0, 0.5), 0.7);
  return mesh::makeEllipsoid(level, Vec3(1.4, 0.8, 1.0), p);
}

std::vector<double> velocities(const mesh::SurfaceMesh& cell, Vec3 (*field)(const Vec3&))
{
  std::vector<double> u(3 * static_cast<std::size_t>(cell.numNodes()));
  for (int i = 0; i < cell.numNodes(); ++i) {
    const Vec3 v = field(cell.position(i));
    for (int d = 0; d < 3; ++d) {
      u[3 * static_cast<std::size_t>(i) + d] = v[d];
    }
  }
  return u;
}

const Vec3 kTranslation(0.3, -0.7, 0.2);
const Vec3 kRotation(0.1, 0.4, -0.9);
const Vec3 kPivot(-1.0, 0.5, 2.0);

Vec3 rigidField(const Vec3& x)
{
  return kTranslation + kRotation.cross(x - kPivot);
}
// A deforming field: shear plus a quadratic stretch.
Vec3 deformingField(const Vec3& x)
{
  return Vec3(x[1] + 0.3 * x[0] * x[0], 0.2 * x[1] * x[2] + 0.1 * x[0], -0.1 * x[2]);
}

TEST(CellKinematics, CentroidVelocityIsExactForRigidMotion)
{
  // For a rigid motion the interpolated surface velocity is exact and the centroid moves
  // with U + Omega x (x_c - pivot): equal to round-off (the volume integral is exact).
  const auto cell = tiltedEllipsoid(2);
  const auto u = velocities(cell, rigidField);
  const Vec3 c = mesh::centroid(cell);
  const Vec3 expected = rigidField(c);
  EXPECT_LT((scene::centroidVelocity(cell, u.data()) - expected).norm(), 1e-12);
}

TEST(CellKinematics, CentroidVelocityMatchesTheRateOfTheDiscreteCentroid)
{
  // A deforming field also changes the element parametrisation (eq 3.17), which the
  // interpolated velocity ignores: the difference from the finite-difference rate of
  // mesh::centroid is a discretisation error that must fall with the mesh size.
  std::vector<double> errors;
  for (int level : {1, 2, 3}) {
    auto cell = tiltedEllipsoid(level);
    const auto u = velocities(cell, deformingField);
    const Vec3 rate = scene::centroidVelocity(cell, u.data());
    const std::vector<double> x0 = cell.positions();
    const double eps = 1e-6;
    std::vector<double> xp(x0), xm(x0);
    for (std::size_t k = 0; k < x0.size(); ++k) {
      xp[k] += eps * u[k];
      xm[k] -= eps * u[k];
    }
    cell.setPositions(xp);
    const Vec3 cp = mesh::centroid(cell);
    cell.setPositions(xm);
    const Vec3 cm = mesh::centroid(cell);
    errors.push_back(((cp - cm) / (2.0 * eps) - rate).norm());
  }
  EXPECT_LT(errors[2], 2e-3);            // level 3: a fraction of a percent of |rate| ~ 1
  EXPECT_LT(errors[2], 0.3 * errors[0]); // and it converges
}

TEST(CellKinematics, RigidMotionFitRecoversTheMotion)
{
  const auto cell = tiltedEllipsoid(1);
  const auto u = velocities(cell, rigidField);
  const Vec3 c = mesh::centroid(cell);
  const auto motion = scene::rigidMotionFit(cell, u.data(), c);
  EXPECT_LT((motion.translation - rigidField(c)).norm(), 1e-12);
  EXPECT_LT((motion.rotation - kRotation).norm(), 1e-12);
}

TEST(FixedHeightConstraint, RemovesTheCentroidRiseOfEachConstrainedCell)
{
  // Two cells in one state; only the second is constrained. Afterwards its centroid rise
  // rate is zero to round-off, its horizontal velocities are untouched, and the first
  // cell's velocities are unchanged.
  const auto first = tiltedEllipsoid(1);
  mesh::Placement p;
  p.centre = Vec3(3.0, 1.5, 0.0);
  const auto second = mesh::makeSphere(2, 1.0, p);
  std::vector<double> positions = first.positions();
  const auto secondPositions = second.positions();
  positions.insert(positions.end(), secondPositions.begin(), secondPositions.end());
  std::vector<double> u = velocities(first, deformingField);
  const auto u2 = velocities(second, deformingField);
  u.insert(u.end(), u2.begin(), u2.end());
  const std::vector<double> before = u;

  scene::FixedHeightConstraint constraint({second}, {first.numNodes()});
  constraint.apply(positions, u);

  const std::size_t offset = 3 * static_cast<std::size_t>(first.numNodes());
  for (std::size_t k = 0; k < offset; ++k) {
    EXPECT_EQ(u[k], before[k]);
  }
  const double removed = before[offset + 1] - u[offset + 1];
  EXPECT_GT(std::abs(removed), 0.1); // the field does lift this cell
  for (std::size_t k = offset; k < u.size(); ++k) {
    EXPECT_DOUBLE_EQ(u[k], before[k] - ((k - offset) % 3 == 1 ? removed : 0.0));
  }
  EXPECT_NEAR(scene::centroidVelocity(second, u.data() + offset)[1], 0.0, 1e-13);
}

} // namespace
