// The tether run's domain check (NodesInFluid2D.hpp, TimeIntegrator::setDomainCheck): a
// Runge-Kutta attempt whose stage state puts a node through the wall is a rejected step,
// not the end of the run. The check asks the model's domain::Domain for the walls.
#include <capsula/core/Error.hpp>
#include <capsula/domain/Domain.hpp>
#include <capsula/scene2d/NodesInFluid2D.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace capsula;
using namespace capsula::scene2d;

namespace {

// A node relaxing onto the film height h = 0.005 at the rate mu: y' = -mu (y - h), x' = 0.
// mu h_step >> 1 is the stiff mode of a freshly tethered a/b = 0.25 cell (docs/tether2d-results.md).
constexpr double film = 0.005;
constexpr double rate = 5000.0;

timeint::TimeIntegrator relaxingNode(bool adaptive)
{
  timeint::TimeIntegrationSettings settings;
  settings.method = "RKF45";
  settings.adaptive = adaptive;
  settings.tolerance = 1e-6;
  settings.initialStep = 2e-3; // the preparation's step that the a/b = 0.25 cells were tethered with
  return timeint::TimeIntegrator(settings, [](double, const std::vector<double>& y, std::vector<double>& dydt) {
    dydt[0] = 0.0;
    dydt[1] = -rate * (y[1] - film);
  });
}

void checkAboveWall(const std::vector<double>& y)
{
  requireNodesInFluid(domain::Domain::aboveWall(), y);
}

// What the tether run does: the same integrator with the wall as its domain.
timeint::TimeIntegrator relaxingNodeAboveTheWall(bool adaptive)
{
  timeint::TimeIntegrator integrator = relaxingNode(adaptive);
  integrator.setDomainCheck(checkAboveWall);
  return integrator;
}

} // namespace

// The node is found by its height alone (the second of its two coordinates), on the wall,
// through it or at a NaN height; a channel's upper wall counts as well, and without walls
// nothing is outside.
TEST(NodesInFluid2D, FindsTheFirstNodeOnOrThroughAWallOfTheDomain)
{
  const domain::Domain above = domain::Domain::aboveWall();
  const std::vector<double> nodes{0.0, 1.0, 5.0, 0.0, 1.0, -1.0};
  EXPECT_EQ(above.firstPointOutsideFluid(nodes.data(), 1, 2), -1);
  EXPECT_EQ(above.firstPointOutsideFluid(nodes.data(), 3, 2), 1);
  const double nan[2] = {0.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_EQ(above.firstPointOutsideFluid(nan, 1, 2), 0);
  const std::vector<double> tall{0.0, 1.0, 5.0, 3.0};
  EXPECT_EQ(domain::Domain::channel(2.0).firstPointOutsideFluid(tall.data(), 2, 2), 1);
  EXPECT_EQ(domain::Domain::unbounded().firstPointOutsideFluid(nodes.data(), 3, 2), -1);
  EXPECT_THROW(above.firstPointOutsideFluid(nodes.data(), 1, 4), core::Error); // 2D or 3D points only

  EXPECT_NO_THROW(requireNodesInFluid(above, {0.0, 1.0, 2.0, 1e-9}));
  try {
    requireNodesInFluid(above, {0.0, 1.0, 2.0, -1e-9});
    FAIL() << "a node below the wall must be refused";
  } catch (const timeint::StateOutsideDomain& error) {
    EXPECT_NE(std::string(error.what()).find("node 1 at (2, -1e-09) reached the wall"), std::string::npos)
        << error.what();
  }
  try {
    requireNodesInFluid(domain::Domain::channel(2.0), tall);
    FAIL() << "a node above the upper wall must be refused";
  } catch (const timeint::StateOutsideDomain& error) {
    EXPECT_NE(std::string(error.what()).find("node 1 at (5, 3) reached the upper wall"), std::string::npos)
        << error.what();
  }
}

// The bug: after tethering an a/b = 0.25 cell at its sharp end, the first RKF45 attempt with
// the preparation's step drove node 1 through the wall in a stage state and the run stopped
// ("the cell has touched the wall") although smaller steps stay above it.
TEST(NodesInFluid2D, TetheredAbQuarterCellStageThroughTheWallIsARejectedStepNotAFailure)
{
  // Without the domain check the first attempt's second stage, y0 + h/4 k1 = 0.02 - 0.0375,
  // is evaluated below the wall (where the wall kernel would meet its image).
  {
    timeint::TimeIntegrationSettings settings;
    settings.method = "RKF45";
    settings.tolerance = 1e-6;
    settings.initialStep = 2e-3;
    bool belowTheWall = false;
    timeint::TimeIntegrator plain(settings, [&](double, const std::vector<double>& y, std::vector<double>& dydt) {
      belowTheWall = belowTheWall || y[1] <= 0.0;
      dydt[0] = 0.0;
      dydt[1] = -rate * (y[1] - film);
    });
    timeint::IntegrationState state = plain.start(0.0, {0.3, 0.02});
    plain.step(state, 1.0);
    EXPECT_TRUE(belowTheWall);
  }
  timeint::TimeIntegrator integrator = relaxingNodeAboveTheWall(true);
  timeint::IntegrationState state = integrator.start(0.0, {0.3, 0.02});
  const timeint::StepReport first = integrator.step(state, 1.0);
  EXPECT_LT(first.stepSize, 2e-3);
  EXPECT_GT(state.statistics.rejectedSteps, 0);
  // The domain's rejections are counted apart from the error control's.
  EXPECT_GT(state.statistics.rejectedOutsideDomain, 0);
  EXPECT_LE(state.statistics.rejectedOutsideDomain, state.statistics.rejectedSteps);
  EXPECT_GT(state.y[1], 0.0);
  const double end = 2e-3;
  while (state.time < end) {
    integrator.step(state, end);
    ASSERT_GT(state.y[1], 0.0);
    ASSERT_EQ(state.y[0], 0.3);
  }
  // y(t) = h + (y0 - h) e^{-mu t}. An accepted step has |x5 - x4| <= 0.5 eps / 0.75^4
  // = 1.6e-6 (eq A.52 and the controller's acceptance at s >= 0.75), and the stiff mode damps
  // the earlier steps' errors, so the end is within a few of those.
  const double exact = film + (0.02 - film) * std::exp(-rate * end);
  EXPECT_NEAR(state.y[1], exact, 5e-6) << "error " << state.y[1] - exact;
}

TEST(NodesInFluid2D, FixedStepsThroughTheWallFailWithAClearError)
{
  timeint::TimeIntegrator integrator = relaxingNodeAboveTheWall(false);
  timeint::IntegrationState state = integrator.start(0.0, {0.3, 0.02});
  try {
    integrator.step(state, 1.0);
    FAIL() << "a fixed step through the wall must fail";
  } catch (const core::NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("reached the wall"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("fixed"), std::string::npos) << error.what();
  }
  EXPECT_EQ(state.time, 0.0); // the last accepted state
  EXPECT_EQ(state.y[1], 0.02);
}

TEST(NodesInFluid2D, ACellDrivenIntoTheWallFailsWhenTheStepCollapses)
{
  timeint::TimeIntegrationSettings settings;
  settings.method = "RKF45";
  settings.minimumStep = 1e-12;
  timeint::TimeIntegrator integrator(settings, [](double, const std::vector<double>&, std::vector<double>& dydt) {
    dydt[0] = 0.0;
    dydt[1] = -1.0; // towards the wall whatever the gap
  });
  integrator.setDomainCheck(checkAboveWall);
  timeint::IntegrationState state = integrator.start(0.0, {0.0, 1e-15});
  EXPECT_THROW(integrator.step(state, 1.0), core::NumericalError);
  EXPECT_EQ(state.time, 0.0);
  EXPECT_EQ(state.y[1], 1e-15);
}
