// The undisturbed flows of domain::FlowProfile: exact values of the profiles, their
// derivatives against central differences, the wall velocities and shear rates, the flux.
#include <capsula/core/Error.hpp>
#include <capsula/domain/FlowProfile.hpp>

#include <gtest/gtest.h>

namespace {

namespace domain = capsula::domain;

// Poiseuille flow u = y (1 - y / H): no slip on both walls, the centre-line velocity H / 4,
// the shear rate 1 at the lower wall and -1 at the upper one (so +1 into the fluid at both).
TEST(FlowProfile, PoiseuilleFlowInAChannel)
{
  const double height = 6.0;
  const domain::FlowProfile flow(domain::FlowProfileKind::Poiseuille, domain::Domain::channel(height));
  EXPECT_FALSE(flow.isLinear());
  EXPECT_EQ(flow.velocity(0.0), 0.0);
  EXPECT_EQ(flow.velocity(height), 0.0);
  EXPECT_DOUBLE_EQ(flow.velocity(height / 2), height / 4);
  EXPECT_EQ(flow.shearRate(0.0), 1.0);
  EXPECT_EQ(flow.shearRate(height), -1.0);
  EXPECT_EQ(flow.shearRate(height / 2), 0.0);
  const auto channel = domain::Domain::channel(height);
  EXPECT_EQ(flow.wallVelocity(channel.walls()[0]), 0.0);
  EXPECT_EQ(flow.wallVelocity(channel.walls()[1]), 0.0);
  EXPECT_EQ(flow.wallShearRate(channel.walls()[0]), 1.0);
  EXPECT_EQ(flow.wallShearRate(channel.walls()[1]), 1.0);
  // Simpson's rule is exact for the quadratic profile: int_0^H f dy = H^2 / 6.
  const double simpson = height / 6.0 * (flow.velocity(0) + 4 * flow.velocity(height / 2) + flow.velocity(height));
  EXPECT_NEAR(flow.fluxPerWidth(), simpson, 1e-14);
  EXPECT_DOUBLE_EQ(flow.fluxPerWidth(), height * height / 6.0);
}

// Shear in a channel is plane Couette flow: the upper wall slides at H, the shear rate is 1
// everywhere and -1 seen from the upper wall's fluid side (the wall drags the fluid forward).
TEST(FlowProfile, CouetteFlowInAChannel)
{
  const auto channel = domain::Domain::channel(5.0);
  const domain::FlowProfile flow(domain::FlowProfileKind::Shear, channel);
  EXPECT_TRUE(flow.isLinear());
  EXPECT_EQ(flow.wallVelocity(channel.walls()[1]), 5.0);
  EXPECT_EQ(flow.wallShearRate(channel.walls()[1]), -1.0);
  EXPECT_DOUBLE_EQ(flow.fluxPerWidth(), 12.5);
  EXPECT_NE(flow.describe().find("plane Couette flow"), std::string::npos) << flow.describe();
}

// The gradient is the derivative of the velocity (central differences are exact for
// polynomials of degree <= 2 up to round-off, 1e-9 with a step of 1e-3 at these sizes).
TEST(FlowProfile, GradientIsTheDerivativeOfTheVelocity)
{
  for (auto kind : {domain::FlowProfileKind::Shear, domain::FlowProfileKind::Poiseuille}) {
    const domain::FlowProfile flow(kind, domain::Domain::channel(3.0));
    for (double y : {0.1, 0.9, 1.5, 2.7}) {
      const double x[3] = {0.4, y, -2.0};
      const auto gradient = flow.gradientAt(x);
      const double step = 1e-3;
      const double up[3] = {0.4, y + step, -2.0}, down[3] = {0.4, y - step, -2.0};
      const double difference = (flow.velocityAt(up)[0] - flow.velocityAt(down)[0]) / (2 * step);
      EXPECT_NEAR(gradient[1], difference, 1e-9) << domain::flowProfileName(kind) << " y = " << y;
      for (int k = 0; k < 9; ++k) {
        if (k != 1) {
          EXPECT_EQ(gradient[static_cast<std::size_t>(k)], 0.0);
        }
      }
      EXPECT_EQ(flow.velocityAt(x)[1], 0.0);
      EXPECT_EQ(flow.velocityAt(x)[2], 0.0);
    }
  }
}

TEST(FlowProfile, PoiseuilleNeedsAChannel)
{
  try {
    domain::FlowProfile(domain::FlowProfileKind::Poiseuille, domain::Domain::aboveWall());
    FAIL() << "Poiseuille flow above one wall was accepted";
  } catch (const capsula::core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'Flow/Profile' = 'Poiseuille'"), std::string::npos) << what;
    EXPECT_NE(what.find("'Wall/Channel height' is 0"), std::string::npos) << what;
  }
  // Simple shear above one wall has no finite flux.
  EXPECT_THROW(domain::FlowProfile(domain::FlowProfileKind::Shear, domain::Domain::aboveWall()).fluxPerWidth(),
               capsula::core::InputError);
}

} // namespace
