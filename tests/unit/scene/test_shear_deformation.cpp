#include <capsula/mesh/EquivalentEllipsoid.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/scene/ShearDeformation.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

namespace mesh = capsula::mesh;
using capsula::scene::shearDeformation;

mesh::EquivalentEllipsoid exactEllipsoid(const mesh::Vec3& semiAxes, const mesh::Mat3& axes)
{
  mesh::EquivalentEllipsoid e;
  e.semiAxes = semiAxes;
  e.axes = axes;
  e.centre = mesh::Vec3::Zero();
  e.volume = 4.0 * M_PI / 3.0 * semiAxes.prod();
  return e;
}

TEST(ShearDeformation, UsesTheShearPlaneNotTheSortedAxes)
{
  // A capsule in shear: long axis 1.3 tilted 30 degrees in xy, short 0.7 in xy, the
  // vorticity axis (z) the middle one, 1.0. Sorted by length D12 would be (1.3-1)/(2.3).
  const mesh::Mat3 R = mesh::rotationAboutAxis(mesh::Vec3::UnitZ(), M_PI / 6.0);
  mesh::Mat3 axes;
  axes << R.col(0), R.col(2), R.col(1); // sorted by length: 1.3 (x'), 1.0 (z), 0.7 (y')
  axes.col(2) *= -1.0;                  // keep det = +1 as the mesh package does
  const auto d = shearDeformation(exactEllipsoid(mesh::Vec3(1.3, 1.0, 0.7), axes));
  EXPECT_DOUBLE_EQ(d.D12, 0.6 / 2.0);
  EXPECT_DOUBLE_EQ(d.D13, 0.3 / 2.3);
  EXPECT_DOUBLE_EQ(d.D23, 0.3 / 1.7);
  EXPECT_NEAR(d.inclinationDegrees, 30.0, 1e-12);
  EXPECT_DOUBLE_EQ(d.semiAxes[2], 1.0);
}

TEST(ShearDeformation, InclinationIsFoldedAndSigned)
{
  // An axis direction and its opposite are the same axis: -150 degrees is +30, and a
  // tilt towards -y is negative.
  for (double degrees : {-150.0, 30.0, 210.0}) {
    const mesh::Mat3 R = mesh::rotationAboutAxis(mesh::Vec3::UnitZ(), degrees * M_PI / 180.0);
    const auto d = shearDeformation(exactEllipsoid(mesh::Vec3(2.0, 1.5, 1.0), R));
    EXPECT_NEAR(d.inclinationDegrees, 30.0, 1e-10) << degrees;
  }
  const mesh::Mat3 R = mesh::rotationAboutAxis(mesh::Vec3::UnitZ(), -20.0 * M_PI / 180.0);
  EXPECT_NEAR(shearDeformation(exactEllipsoid(mesh::Vec3(2.0, 1.5, 1.0), R)).inclinationDegrees, -20.0, 1e-10);
}

TEST(ShearDeformation, OfADiscreteEllipsoidMatchesItsSemiAxes)
{
  // A level-3 ellipsoid (1.3, 0.7, 1.0) tilted 30 degrees: the inertia-equivalent
  // semi-axes carry the O(h^4) surface error of the mesh (~1e-5 here), so D12 = 0.3 to
  // 1e-4 and the angle to 0.01 degree.
  mesh::Placement placement;
  placement.rotation = mesh::rotationAboutAxis(mesh::Vec3::UnitZ(), M_PI / 6.0);
  placement.centre = mesh::Vec3(0.3, 2.0, -0.1);
  const auto cell = mesh::makeEllipsoid(3, mesh::Vec3(1.3, 0.7, 1.0), placement);
  const auto d = shearDeformation(mesh::equivalentEllipsoid(cell));
  EXPECT_NEAR(d.D12, 0.3, 1e-4);
  EXPECT_NEAR(d.D13, 0.3 / 2.3, 1e-4);
  EXPECT_NEAR(d.D23, 0.3 / 1.7, 1e-4);
  EXPECT_NEAR(d.inclinationDegrees, 30.0, 1e-2);
}

} // namespace
