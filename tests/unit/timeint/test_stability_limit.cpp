// The stability limit of adaptive steps (TimeIntegrationSettings::stabilityLimit): the
// methods' real stability boundaries, the power-iteration estimate of the fastest decay
// rate, and what the limit does on a stiff problem that the error control alone lets blow
// up.
#include "capsula/timeint/ButcherTableau.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace ti = capsula::timeint;

// The boundaries: RK4's 2.78529356 and Dormand-Prince's 3.3066 are the published ones
// (Hairer & Wanner, Solving ODEs II, Section IV.2); for RKF45 the code's values (3.0200 for
// the 4th-order solution that advances by default, 3.6777 with local extrapolation) are
// checked by evaluating R at the boundary and just beyond it.
TEST(StabilityLimit, RealStabilityBoundaries)
{
  EXPECT_NEAR(ti::realStabilityBoundary(ti::classicalRungeKutta4()), 2.785293563, 1e-8);
  EXPECT_NEAR(ti::realStabilityBoundary(ti::dormandPrince45()), 3.3066, 1e-4);
  EXPECT_NEAR(ti::realStabilityBoundary(ti::rungeKuttaFehlberg45()), 3.0200, 1e-4);
  EXPECT_NEAR(ti::realStabilityBoundary(ti::rungeKuttaFehlberg45Extrapolated()), 3.6777, 1e-4);
  for (const auto& tableau :
       {ti::rungeKuttaFehlberg45(), ti::rungeKuttaFehlberg45Extrapolated(), ti::dormandPrince45()}) {
    const double r = ti::realStabilityBoundary(tableau);
    EXPECT_LE(std::abs(ti::stabilityFunction(tableau, -r)), 1.0 + 1e-9) << tableau.name;
    EXPECT_GT(std::abs(ti::stabilityFunction(tableau, -r - 1e-3)), 1.0) << tableau.name;
  }
  // The stability function is exp(z) to the order of the method near 0.
  const auto rkf = ti::rungeKuttaFehlberg45();
  EXPECT_NEAR(ti::stabilityFunction(rkf, -0.01), std::exp(-0.01), 1e-12);
}

namespace {

// y' = -diag(rates) y + a slow forcing: the fast components decay at once and then only
// stability matters; the slow one needs steps ~0.1 for a loose tolerance.
ti::RightHandSide stiffLinear(const std::vector<double>& rates)
{
  return [rates](double t, const std::vector<double>& y, std::vector<double>& f) {
    for (std::size_t i = 0; i < y.size(); ++i) {
      f[i] = -rates[i] * y[i] + (i == 0 ? std::cos(t) : 0.0);
    }
  };
}

ti::TimeIntegrationSettings loose(bool limit)
{
  ti::TimeIntegrationSettings s;
  s.method = "RKF45";
  s.tolerance = 1e-3; // loose: the error control lets the step grow past 3.02 / 400
  s.initialStep = 1e-4;
  s.endTime = 4.0;
  s.stabilityLimit = limit;
  return s;
}

} // namespace

// The estimate finds the fastest rate, and no accepted step exceeds 0.8 r / rho.
TEST(StabilityLimit, StepsStayInsideTheStabilityRegion)
{
  const std::vector<double> rates{1.0, 50.0, 400.0};
  ti::TimeIntegrator integrator(loose(true), stiffLinear(rates));
  auto state = integrator.start(0.0, {0.0, 1.0, 1.0});
  const double bound = 0.8 * ti::realStabilityBoundary(ti::rungeKuttaFehlberg45()) / 400.0;
  double largestFast = 0.0;
  while (state.time < 4.0) {
    const auto report = integrator.step(state, 4.0);
    EXPECT_LE(report.stepSize, bound * (1.0 + 1e-3)) << "t = " << state.time;
    largestFast = std::max(largestFast, std::abs(state.y[2]));
  }
  // 12 power iterations from a vector with every mode in it reach rho to 0.1%.
  EXPECT_NEAR(state.stabilityStep, bound, 1e-3 * bound);
  EXPECT_LE(largestFast, 1.0); // the fast mode only decays
  EXPECT_NEAR(state.y[0], (std::cos(4.0) + std::sin(4.0) - std::exp(-4.0)) / 2.0, 1e-3);
}

// Without the limit the same run is not stable: the error control accepts steps beyond the
// boundary, the fast mode grows between rejections and the step size chatters (here the
// fast component reaches 1e-3..1, limited only by the error control). This is what the
// limit prevents; if the error control alone kept it below 1e-6 this test would not
// discriminate anything.
TEST(StabilityLimit, WithoutItTheErrorControlAcceptsUnstableSteps)
{
  const std::vector<double> rates{1.0, 50.0, 400.0};
  ti::TimeIntegrator integrator(loose(false), stiffLinear(rates));
  auto state = integrator.start(0.0, {0.0, 1.0, 1.0});
  const double bound = ti::realStabilityBoundary(ti::rungeKuttaFehlberg45()) / 400.0;
  int beyond = 0;
  double fastAfterDecay = 0.0;
  while (state.time < 4.0) {
    const auto report = integrator.step(state, 4.0);
    beyond += report.stepSize > bound ? 1 : 0;
    if (state.time > 1.0) { // exp(-400) later: anything left is the instability's
      fastAfterDecay = std::max(fastAfterDecay, std::abs(state.y[2]));
    }
  }
  EXPECT_GT(beyond, 0);
  EXPECT_GT(fastAfterDecay, 1e-6);
}

// The limit's state goes through a checkpoint record, so a restart repeats the run bit for
// bit; stateChangedOutside() makes the next step estimate again.
TEST(StabilityLimit, RestartAndOutsideChanges)
{
  const std::vector<double> rates{1.0, 50.0, 400.0};
  ti::TimeIntegrator integrator(loose(true), stiffLinear(rates));
  auto state = integrator.start(0.0, {0.0, 1.0, 1.0});
  for (int k = 0; k < 15; ++k) {
    integrator.step(state, 4.0);
  }
  auto copy = ti::fromRecord(ti::toRecord(state), "test");
  ti::TimeIntegrator other(loose(true), stiffLinear(rates));
  for (int k = 0; k < 20; ++k) {
    integrator.step(state, 4.0);
    other.step(copy, 4.0);
  }
  EXPECT_EQ(std::memcmp(state.y.data(), copy.y.data(), state.y.size() * sizeof(double)), 0);
  EXPECT_EQ(state.statistics.rhsEvaluations, copy.statistics.rhsEvaluations);

  const auto before = state.statistics.rhsEvaluations;
  ti::stateChangedOutside(state);
  integrator.step(state, 4.0);
  // 6 stages and 3 warm-started power iterations (RKF45 is not FSAL, so no stage is lost).
  EXPECT_EQ(state.statistics.rhsEvaluations - before, 6 + 3);
  EXPECT_EQ(state.stepsSinceStabilityEstimate, 1);
}
