// The geometry of domain::Domain: nearest images, folding into the box, distances to the
// walls, the fluid's extent, and the shapes that are not domains.
#include <capsula/core/Error.hpp>
#include <capsula/domain/Domain.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace {

namespace domain = capsula::domain;

domain::Domain periodicBox(double lx, double lz, double height = 0.0)
{
  domain::DomainShape shape;
  shape.channelHeight = height;
  shape.periodX = lx;
  shape.periodZ = lz;
  return domain::Domain(shape);
}

// Each periodic component is brought into [-L/2, L/2] by a whole number of periods; the
// wall normal and a non-periodic direction are left alone. Exact in binary for these values
// up to one rounding of d - n L.
TEST(Domain, NearestImageShiftsByWholePeriods)
{
  const auto box = periodicBox(3.0, 2.0);
  double d[3] = {7.3, 11.0, -4.9};
  box.nearestImage(d);
  EXPECT_NEAR(d[0], 1.3, 1e-14);  // 7.3 - 2 * 3
  EXPECT_EQ(d[1], 11.0);          // y is never periodic
  EXPECT_NEAR(d[2], -0.9, 1e-14); // -4.9 + 2 * 2
  double e[3] = {-1.6, 0.0, 0.99};
  box.nearestImage(e);
  EXPECT_NEAR(e[0], 1.4, 1e-14); // -1.6 + 3: the image 1.4 away is nearer than 1.6
  EXPECT_NEAR(e[2], 0.99, 1e-14);
  const auto onlyX = periodicBox(3.0, 0.0);
  double f[3] = {4.0, 0.0, 100.0};
  onlyX.nearestImage(f);
  EXPECT_NEAR(f[0], 1.0, 1e-14);
  EXPECT_EQ(f[2], 100.0); // unbounded along z
  const auto a = std::array<double, 3>{0.2, 1.0, 0.1};
  const auto b = std::array<double, 3>{2.9, 1.5, 1.9};
  const auto s = box.separation(a.data(), b.data());
  EXPECT_NEAR(s[0], 0.3, 1e-14); // 0.2 - 2.9 + 3
  EXPECT_NEAR(s[1], -0.5, 1e-14);
  EXPECT_NEAR(s[2], 0.2, 1e-14); // 0.1 - 1.9 + 2
}

TEST(Domain, FoldingShiftBringsAPointIntoTheBox)
{
  const auto box = periodicBox(2.0, 3.0);
  const double x[3] = {-0.5, 3.0, 7.1};
  const auto shift = box.foldingShift(x);
  EXPECT_EQ(shift[0], 2.0);
  EXPECT_EQ(shift[1], 0.0);
  EXPECT_EQ(shift[2], -6.0);
  EXPECT_NEAR(x[2] + shift[2], 1.1, 1e-14);
  const auto unbounded = domain::Domain::unbounded().foldingShift(x);
  EXPECT_EQ(unbounded[0], 0.0);
  EXPECT_EQ(unbounded[2], 0.0);
}

TEST(Domain, DistanceToTheNearestWall)
{
  const auto channel = domain::Domain::channel(4.0);
  ASSERT_EQ(channel.walls().size(), 2u);
  int nearest = -7;
  const double low[3] = {5.0, 1.0, -3.0};
  EXPECT_EQ(channel.distanceToNearestWall(low, &nearest), 1.0);
  EXPECT_EQ(nearest, 0);
  const double high[3] = {0.0, 3.5, 0.0};
  EXPECT_EQ(channel.distanceToNearestWall(high, &nearest), 0.5);
  EXPECT_EQ(nearest, 1);
  EXPECT_EQ(channel.walls()[1].name, "upper wall");
  const double below[3] = {0.0, -0.2, 0.0};
  EXPECT_EQ(channel.distanceToNearestWall(below, &nearest), -0.2);
  EXPECT_EQ(nearest, 0);
  const double above[3] = {0.0, 4.25, 0.0};
  EXPECT_EQ(channel.distanceToNearestWall(above), -0.25);
  // One wall: the distance is the height; no wall: infinite, no index.
  EXPECT_EQ(domain::Domain::aboveWall().distanceToNearestWall(high), 3.5);
  EXPECT_EQ(domain::Domain::unbounded().distanceToNearestWall(high, &nearest), std::numeric_limits<double>::infinity());
  EXPECT_EQ(nearest, -1);
}

TEST(Domain, TheFluidLiesStrictlyBetweenTheWalls)
{
  const auto channel = domain::Domain::channel(4.0);
  const double inside[3] = {0.0, 2.0, 0.0};
  const double onLower[3] = {0.0, 0.0, 0.0};
  const double onUpper[3] = {0.0, 4.0, 0.0};
  const double nan[3] = {0.0, std::nan(""), 0.0};
  const double farUp[3] = {0.0, 1e9, 0.0};
  EXPECT_TRUE(channel.inFluid(inside));
  EXPECT_FALSE(channel.inFluid(onLower));
  EXPECT_FALSE(channel.inFluid(onUpper));
  EXPECT_FALSE(channel.inFluid(nan));
  EXPECT_FALSE(channel.inFluid(farUp));
  EXPECT_TRUE(domain::Domain::aboveWall().inFluid(farUp));
  EXPECT_FALSE(domain::Domain::aboveWall().inFluid(nan));
  const double belowEverything[3] = {0.0, -1e9, 0.0};
  EXPECT_TRUE(domain::Domain::unbounded().inFluid(belowEverything));
}

TEST(Domain, ShapesThatAreNotDomainsAreRefused)
{
  EXPECT_THROW(periodicBox(-1.0, 0.0), capsula::core::InputError);
  EXPECT_THROW(periodicBox(0.0, std::nan("")), capsula::core::InputError);
  EXPECT_THROW(periodicBox(std::numeric_limits<double>::infinity(), 0.0), capsula::core::InputError);
  EXPECT_THROW(domain::Domain::channel(-2.0), capsula::core::InputError);
  domain::DomainShape upperOnly;
  upperOnly.lowerWall = false;
  upperOnly.channelHeight = 3.0;
  EXPECT_THROW(domain::Domain{upperOnly}, capsula::core::InputError);
}

TEST(Domain, DescribesItself)
{
  EXPECT_EQ(domain::Domain::unbounded().describe(), "unbounded fluid");
  EXPECT_EQ(domain::Domain::aboveWall().describe(), "the fluid above the wall y = 0");
  EXPECT_EQ(periodicBox(20.0, 0.0, 10.0).describe(), "a channel 0 < y < 10, periodic along x (L_x = 20)");
  EXPECT_EQ(periodicBox(20.0, 8.0).describe(),
            "the fluid above the wall y = 0, periodic along x and z (L_x = 20, L_z = 8)");
  EXPECT_TRUE(periodicBox(0.0, 8.0).isPeriodic());
  EXPECT_FALSE(periodicBox(0.0, 8.0).isPeriodic(domain::flowAxis));
  EXPECT_FALSE(domain::Domain::channel(3.0).isPeriodic());
}

} // namespace
