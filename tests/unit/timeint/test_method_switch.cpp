// Method Auto (AutoSwitchingMethod.cpp): RKF45 with the stability limit where the problem is not
// stiff, ROS34PW2 while the limit holds the explicit step far below what accuracy
// allows, and back when the stiffness goes away; decisions by counted work, so a restart
// repeats them.
#include "capsula/timeint/DenseLinearisedSystem.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace ti = capsula::timeint;

namespace {

// y0' = cos t - y0 (slow, sets the accuracy), y1' = -k(t) (y1 - sin t) with
// k = 4000 / (1 + exp(20 (t - 2))) + 0.5: stiff until t ~ 2, soft after.
double rate(double t)
{
  return 4000.0 / (1.0 + std::exp(20.0 * (t - 2.0))) + 0.5;
}

void fadingStiffness(double t, const std::vector<double>& y, std::vector<double>& f)
{
  f[0] = std::cos(t) - y[0];
  f[1] = -rate(t) * (y[1] - std::sin(t));
}

// Exact Jacobian with a dense solve, reporting each solve as `iterations` Krylov
// iterations so that a stiff step costs what it costs with a capsule's iterative solver.
class KrylovLikeSystem final : public ti::LinearisedSystem {
public:
  explicit KrylovLikeSystem(int iterations)
      : iterations_(iterations), dense_([](double t, const std::vector<double>&, std::vector<double>& J) {
          J = {-1.0, 0.0, 0.0, -rate(t)};
        })
  {}
  void linearise(double t, const std::vector<double>& y) override { dense_.linearise(t, y); }
  ti::LinearSolveReport solve(double shift, const std::vector<double>& r, std::vector<double>& x,
                              double residual) override
  {
    auto report = dense_.solve(shift, r, x, residual);
    report.iterations = iterations_;
    return report;
  }
  std::string settingsHint() const override { return ""; }

private:
  int iterations_;
  ti::DenseLinearisedSystem dense_;
};

ti::TimeIntegrationSettings autoSettings(double end)
{
  ti::TimeIntegrationSettings s;
  s.method = "Auto";
  s.tolerance = 1e-5;
  s.initialStep = 1e-3;
  s.endTime = end;
  return s;
}

} // namespace

// Where nothing is stiff Auto is RKF45 with the stability limit, bit for bit.
TEST(MethodSwitch, StaysExplicitWhereNothingIsStiff)
{
  const ti::RightHandSide rotation = [](double, const std::vector<double>& y, std::vector<double>& f) {
    f[0] = -y[1];
    f[1] = y[0];
  };
  auto autoSettings_ = autoSettings(6.0);
  ti::TimeIntegrator automatic(autoSettings_, rotation);
  automatic.setLinearisedSystem(std::make_shared<KrylovLikeSystem>(8));
  auto explicitSettings = autoSettings_;
  explicitSettings.method = "RKF45";
  explicitSettings.stabilityLimit = true;
  ti::TimeIntegrator rkf45(explicitSettings, rotation);
  auto a = automatic.start(0.0, {1.0, 0.0});
  auto b = rkf45.start(0.0, {1.0, 0.0});
  while (a.time < 6.0) {
    automatic.step(a, 6.0);
    rkf45.step(b, 6.0);
  }
  EXPECT_EQ(a.statistics.methodSwitches, 0);
  EXPECT_EQ(a.statistics.stiffSteps, 0);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.time, b.time);
}

// While k = 4000 the stability limit holds RKF45 at 0.8 * 3.02 / 4000 = 6e-4, where
// ROS34PW2 takes steps 20-100 times larger; Auto hands over within the first steps. As k
// falls (t ~ 2) the solution turns fast and the stiff method's steps shrink to a few
// times RKF45's limit, where 37 applications a step no longer pay: RKF45 takes over for
// good (the remembered stiff rate keeps it from switching back while the limit still
// binds), ending close to the exact slow component.
TEST(MethodSwitch, SwitchesToTheStiffMethodAndBack)
{
  const auto s = autoSettings(6.0);
  ti::TimeIntegrator integrator(s, fadingStiffness);
  integrator.setLinearisedSystem(std::make_shared<KrylovLikeSystem>(8));
  auto state = integrator.start(0.0, {1.0, 0.0});
  double firstStiff = -1.0, backToExplicit = -1.0;
  std::vector<std::string> reasons;
  while (state.time < s.endTime) {
    const bool wasStiff = state.stiffActive;
    const auto report = integrator.step(state, s.endTime);
    if (!report.switchReason.empty()) {
      reasons.push_back(report.switchReason);
    }
    if (!wasStiff && state.stiffActive && firstStiff < 0.0) {
      firstStiff = state.time;
    }
    if (firstStiff >= 0.0 && !state.stiffActive && backToExplicit < 0.0) {
      backToExplicit = state.time;
    }
  }
  EXPECT_GE(firstStiff, 0.0);
  EXPECT_LT(firstStiff, 0.5);
  EXPECT_GT(backToExplicit, 1.5); // not while the stiff method takes large steps
  EXPECT_LT(backToExplicit, 2.5);
  EXPECT_FALSE(state.stiffActive);
  EXPECT_EQ(state.statistics.methodSwitches, 2);
  ASSERT_EQ(reasons.size(), 2u);
  EXPECT_NE(reasons[0].find("switched to ROS34PW2"), std::string::npos) << reasons[0];
  EXPECT_NE(reasons[1].find("switched to RKF45"), std::string::npos) << reasons[1];
  // y0 = (cos t + sin t)/2 + e^-t / 2: accurate to a few tens of tolerances.
  const double exact = 0.5 * (std::cos(6.0) + std::sin(6.0)) + 0.5 * std::exp(-6.0);
  EXPECT_NEAR(state.y[0], exact, 1e-4);
  EXPECT_GT(state.statistics.stiffSteps, 5);
  EXPECT_LT(state.statistics.stiffSteps, state.statistics.acceptedSteps);
}

// A restart in the stiff phase continues bit for bit (the active method and the counters
// that drive the decisions are part of the state).
TEST(MethodSwitch, RestartInTheStiffPhaseIsBitForBit)
{
  const auto s = autoSettings(4.0);
  const auto finish = [&](ti::IntegrationState state) {
    ti::TimeIntegrator integrator(s, fadingStiffness);
    integrator.setLinearisedSystem(std::make_shared<KrylovLikeSystem>(8));
    while (state.time < s.endTime) {
      integrator.step(state, s.endTime);
    }
    return state;
  };
  ti::TimeIntegrator integrator(s, fadingStiffness);
  integrator.setLinearisedSystem(std::make_shared<KrylovLikeSystem>(8));
  auto state = integrator.start(0.0, {1.0, 0.0});
  while ((!state.stiffActive || state.statistics.stiffSteps < 4) && state.time < s.endTime) {
    integrator.step(state, s.endTime);
  }
  ASSERT_TRUE(state.stiffActive);
  const auto restarted = finish(ti::fromRecord(ti::toRecord(state), "test"));
  const auto uninterrupted = finish(state);
  EXPECT_EQ(restarted.y, uninterrupted.y);
  EXPECT_EQ(restarted.statistics.methodSwitches, uninterrupted.statistics.methodSwitches);
  EXPECT_EQ(restarted.statistics.acceptedSteps, uninterrupted.statistics.acceptedSteps);
}
