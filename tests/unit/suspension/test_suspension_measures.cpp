// The suspension measures on arrangements with a known answer: the hematocrit profile of one
// sphere, the cell-free layer of a sphere in a periodic channel (closed form, also across the
// periodic boundary and far from the box), the wall-normal distribution of given heights.
#include "SuspensionTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/suspension/CellFreeLayer.hpp>
#include <capsula/suspension/HeightDistribution.hpp>
#include <capsula/suspension/HematocritProfile.hpp>
#include <capsula/suspension/SlabVolumes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

namespace domain = capsula::domain;
namespace mesh = capsula::mesh;
namespace suspension = capsula::suspension;
using mesh::Vec3;

using capsula::suspension::testing::periodicChannel;

mesh::SurfaceMesh unitSphereAt(const Vec3& centre, int level)
{
  mesh::Placement placement;
  placement.centre = centre;
  return mesh::makeSphere(level, 1.0, placement);
}

// A unit sphere at y = 2 in the channel 0 < y < 4 of a 5 x 5 box, four slabs of height 1: the
// two middle slabs each hold half the sphere (2 pi / 3 over a slab volume of 25), the outer
// ones nothing; the mean is its volume over 100. The level-4 facets hold each half to 0.054%
// (measured), bounded here by 0.2%; the slabs sum to the mean exactly.
TEST(HematocritProfile, OneSphereInAPeriodicChannel)
{
  const auto box = periodicChannel(5.0, 4.0, 5.0);
  const auto sphere = unitSphereAt(Vec3(1.0, 2.0, 4.5), 4);
  const auto profile = suspension::hematocritProfile({&sphere}, box, 4);
  ASSERT_EQ(profile.fraction.size(), 4u);
  EXPECT_EQ(profile.heights.front(), 0.0);
  EXPECT_EQ(profile.heights.back(), 4.0);
  const double half = 2.0 * M_PI / 3.0 / 25.0;
  EXPECT_EQ(profile.fraction[0], 0.0);
  EXPECT_NEAR(profile.fraction[1], half, 2e-3 * half);
  EXPECT_NEAR(profile.fraction[2], half, 2e-3 * half);
  EXPECT_EQ(profile.fraction[3], 0.0);
  EXPECT_NEAR(profile.mean, 4.0 * M_PI / 3.0 / 100.0, 2e-3 * profile.mean);
  EXPECT_NEAR((profile.fraction[1] + profile.fraction[2]) / 4.0, profile.mean, 1e-15);
  EXPECT_THROW(suspension::hematocritProfile({&sphere}, domain::Domain::channel(4.0), 4), capsula::core::InputError);
}

// A unit sphere whose centre is d from a wall, in a periodic channel of height H with box
// area A: the columns over its disc meet it at d - sqrt(1 - rho^2) from the wall, the others
// count H / 2, so the layer is H/2 + pi (d - H/2) / A - 2 pi / (3 A). Level 4 and 160 x 160
// columns hold it to 3e-4 (measured: the facets lie inside the sphere, the disc's edge is
// sampled at 0.025), bounded here by 1e-3.
double sphereLayer(double d, double height, double area)
{
  return height / 2 + M_PI * (d - height / 2) / area - 2.0 * M_PI / (3.0 * area);
}

// The slab of a periodic channel is the channel's profile; a box above a wall (no channel, no
// periods) takes its top and area as given: the sphere at y = 2 in 0 < y < 4 over an area 10
// holds the same volumes as in the 5 x 5 channel, at 2.5 times the fraction.
TEST(HematocritProfile, SlabOfGivenTopAndArea)
{
  const mesh::SurfaceMesh sphere = unitSphereAt({1.0, 2.0, 3.0}, 2);
  const std::vector<const mesh::SurfaceMesh*> cells{&sphere};
  const auto channel = suspension::hematocritProfile(cells, periodicChannel(5.0, 4.0, 5.0), 4);
  const auto slab = suspension::hematocritProfileInSlab(cells, 4.0, 25.0, 4);
  EXPECT_EQ(slab.fraction, channel.fraction);
  EXPECT_EQ(slab.heights, channel.heights);
  const auto smaller = suspension::hematocritProfileInSlab(cells, 4.0, 10.0, 4);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(smaller.fraction[k], 2.5 * channel.fraction[k], 1e-15);
  }
  // A top through the sphere's middle counts its lower half only: the slab 1 < y < 2.
  const auto cut = suspension::hematocritProfileInSlab(cells, 2.0, 25.0, 2);
  EXPECT_NEAR(cut.fraction[0], 0.0, 1e-15); // nodes on the sphere: none below y = 1 but by round-off
  EXPECT_NEAR(cut.fraction[1], channel.fraction[1], 1e-15);
  EXPECT_THROW(suspension::hematocritProfileInSlab(cells, 0.0, 25.0, 4), capsula::core::InputError);
  EXPECT_THROW(suspension::hematocritProfileInSlab(cells, 4.0, 25.0, 0), capsula::core::InputError);
}

// The thinnest layer is the lowest (highest) node's distance from the lower (upper) wall: for
// a sphere the icosphere's nodes on the unit sphere put it within the chord sag of d - 1.
TEST(CellFreeLayer, ThinnestLayerIsTheExtremeNode)
{
  const mesh::SurfaceMesh sphere = unitSphereAt({0.5, 2.0, -7.0}, 2);
  const mesh::SurfaceMesh other = unitSphereAt({3.0, 3.5, 1.0}, 2);
  const std::vector<const mesh::SurfaceMesh*> cells{&sphere, &other};
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (int n = 0; n < sphere.numNodes(); ++n) {
    lowest = std::min(lowest, sphere.position(n)[1]);
  }
  for (int n = 0; n < other.numNodes(); ++n) {
    highest = std::max(highest, other.position(n)[1]);
  }
  const auto channel = suspension::thinnestCellFreeLayer(cells, domain::Domain::channel(6.0));
  EXPECT_EQ(channel.lower, lowest);
  EXPECT_EQ(channel.upper, 6.0 - highest);
  EXPECT_NEAR(channel.lower, 1.0, 0.05); // the sag of a level-2 icosphere is ~0.01
  EXPECT_NEAR(channel.upper, 1.5, 0.05);
  const auto wall = suspension::thinnestCellFreeLayer(cells, domain::Domain::aboveWall());
  EXPECT_EQ(wall.lower, lowest);
  EXPECT_TRUE(std::isinf(wall.upper));
  EXPECT_THROW(suspension::thinnestCellFreeLayer(cells, domain::Domain::unbounded()), capsula::core::InputError);
}

TEST(CellFreeLayer, OneSphereHasTheClosedForm)
{
  const auto box = periodicChannel(4.0, 8.0, 4.0);
  const auto low = unitSphereAt(Vec3(2.0, 2.0, 2.0), 4);
  const auto layer = suspension::cellFreeLayer({&low}, box, 160, 160);
  EXPECT_NEAR(layer.lower, sphereLayer(2.0, 8.0, 16.0), 1e-3); // 4 - pi / 6 = 3.4764
  EXPECT_EQ(layer.upper, 4.0);                                 // 5 from the top everywhere: every column counts H / 2
  const auto high = unitSphereAt(Vec3(1.0, 6.5, 3.0), 4);
  EXPECT_NEAR(suspension::cellFreeLayer({&high}, box, 160, 160).upper, sphereLayer(1.5, 8.0, 16.0), 1e-3);
}

// The same sphere across the periodic boundary x = 0 (centre at x = 0.1, so 0.9 of its radius
// lies in the neighbouring box) and far outside the box (x = 2 + 3 L_x, z = 2 - 5 L_z):
// positions are unwrapped, the measure folds them. Without the images of the neighbouring
// boxes the crossing sphere's layer comes out 0.356 too high (measured).
TEST(CellFreeLayer, SeesCellsAcrossThePeriodicBoundary)
{
  const auto box = periodicChannel(4.0, 8.0, 4.0);
  const auto inside = unitSphereAt(Vec3(2.0, 2.0, 2.0), 4);
  const auto far = unitSphereAt(Vec3(14.0, 2.0, -18.0), 4);
  const auto crossing = unitSphereAt(Vec3(0.1, 2.0, 3.9), 4);
  const double reference = suspension::cellFreeLayer({&inside}, box, 160, 160).lower;
  EXPECT_NEAR(suspension::cellFreeLayer({&far}, box, 160, 160).lower, reference, 1e-12);
  EXPECT_NEAR(suspension::cellFreeLayer({&crossing}, box, 160, 160).lower, sphereLayer(2.0, 8.0, 16.0), 1e-3);
}

TEST(HeightDistribution, HistogramIsADensity)
{
  const auto channel = domain::Domain::channel(4.0);
  const auto d = suspension::heightDistribution({0.5, 1.5, 1.6, 3.9}, channel, 4);
  ASSERT_EQ(d.density.size(), 4u);
  EXPECT_DOUBLE_EQ(d.density[0], 0.25);
  EXPECT_DOUBLE_EQ(d.density[1], 0.5);
  EXPECT_DOUBLE_EQ(d.density[2], 0.0);
  EXPECT_DOUBLE_EQ(d.density[3], 0.25);
  const auto halves = suspension::heightDistribution({0.5, 1.5, 1.6, 3.9}, channel, 2);
  EXPECT_DOUBLE_EQ(halves.density[0] * 2.0 + halves.density[1] * 2.0, 1.0);
  EXPECT_THROW(suspension::heightDistribution({4.0}, channel, 4), capsula::core::InputError);
  EXPECT_THROW(suspension::heightDistribution({1.0}, domain::Domain::aboveWall(), 4), capsula::core::InputError);
}

} // namespace
