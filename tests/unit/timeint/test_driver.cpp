// The integration driver: output times, restart, steady state, failures, constraints.
#include "TestProblems.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace ti = capsula::timeint;
namespace core = capsula::core;

namespace {

/// A nonlinear, non-autonomous system (forced Van der Pol oscillator, mu = 1) whose step
/// sizes vary along the run, so restart reproducibility is not trivially met.
ti::RightHandSide forcedVanDerPol()
{
  return [](double t, const std::vector<double>& y, std::vector<double>& f) {
    f[0] = y[1];
    f[1] = (1.0 - y[0] * y[0]) * y[1] - y[0] + 0.5 * std::cos(1.3 * t);
  };
}

ti::TimeIntegrationSettings adaptiveSettings(const std::string& method, double endTime)
{
  ti::TimeIntegrationSettings s;
  s.method = method;
  s.tolerance = 1e-8;
  s.endTime = endTime;
  s.initialStep = 1e-3;
  return s;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

void expectSameStatistics(const ti::IntegrationStatistics& a, const ti::IntegrationStatistics& b)
{
  EXPECT_EQ(a.acceptedSteps, b.acceptedSteps);
  EXPECT_EQ(a.rejectedSteps, b.rejectedSteps);
  EXPECT_EQ(a.rhsEvaluations, b.rhsEvaluations);
  EXPECT_TRUE(sameBits(a.smallestStep, b.smallestStep));
  EXPECT_TRUE(sameBits(a.largestStep, b.largestStep));
  EXPECT_TRUE(sameBits(a.lastStep, b.lastStep));
  EXPECT_TRUE(sameBits(a.lastErrorNorm, b.lastErrorNorm));
}

} // namespace

TEST(Driver, ObserversRunExactlyAtOutputTimes)
{
  const auto problem = ti::testing::exponentialDecay();
  for (const std::string method : {"RKF45", "DormandPrince45", "RK4"}) {
    ti::TimeIntegrationSettings s = adaptiveSettings(method, 1.0);
    s.initialStep = method == "RK4" ? 0.03 : 1e-3;
    ti::TimeIntegrator integrator(s, problem.rhs);
    auto state = integrator.start(0.0, problem.y0);
    const ti::OutputSchedule schedule{0.1, true};
    std::vector<double> times;
    std::vector<ti::OutputReason> reasons;
    const auto reason = integrator.integrate(state, schedule, {[&](const ti::IntegrationState& st, ti::OutputReason r) {
                                               times.push_back(st.time);
                                               reasons.push_back(r);
                                             }});
    EXPECT_EQ(reason, ti::StopReason::EndTime);
    ASSERT_EQ(times.size(), 11u) << method;
    EXPECT_EQ(reasons.front(), ti::OutputReason::Start);
    EXPECT_EQ(reasons.back(), ti::OutputReason::End);
    for (std::size_t k = 0; k < times.size(); ++k) {
      // Bit-exact: the step is cut to land on origin + k * interval.
      EXPECT_EQ(times[k], k == 10 ? 1.0 : 0.1 * static_cast<double>(k)) << "output " << k;
      if (k > 0 && k < 10) {
        EXPECT_EQ(reasons[k], ti::OutputReason::Interval);
      }
    }
  }
}

TEST(Driver, OutputTimesDoNotDisturbTheStepSizeMuch)
{
  // Landing on 19 output times costs at most a couple of extra steps each: the step
  // proposed before a cut is resumed after it.
  const auto rhs = forcedVanDerPol();
  for (const std::string method : {"RKF45", "DormandPrince45"}) {
    ti::TimeIntegrator plain(adaptiveSettings(method, 20.0), rhs);
    auto a = plain.start(0.0, {2.0, 0.0});
    plain.integrate(a, {}, {});
    ti::TimeIntegrator withOutputs(adaptiveSettings(method, 20.0), rhs);
    auto b = withOutputs.start(0.0, {2.0, 0.0});
    withOutputs.integrate(b, {1.0, true}, {});
    std::printf("%s: %lld steps without outputs, %lld with 19 output times\n", method.c_str(),
                static_cast<long long>(a.statistics.acceptedSteps), static_cast<long long>(b.statistics.acceptedSteps));
    EXPECT_LE(b.statistics.acceptedSteps, a.statistics.acceptedSteps + 2 * 19);
    // Same accuracy class: the two end states agree to the tolerance's order.
    EXPECT_LT(ti::testing::maxError(a.y, b.y), 1e-5);
  }
}

TEST(Driver, RestartFromAnObservedStateReproducesTheRunBitForBit)
{
  const auto rhs = forcedVanDerPol();
  for (const std::string method : {"RKF45", "DormandPrince45", "RK4"}) {
    ti::TimeIntegrationSettings s = adaptiveSettings(method, 12.0);
    if (method == "RK4") {
      s.initialStep = 0.0137; // does not divide the output interval
    }
    const ti::OutputSchedule schedule{0.75, true};

    // The uninterrupted run; an observer keeps the state at output 7 (t = 5.25) as a
    // checkpoint would, in memory and through the named record of a checkpoint file.
    ti::TimeIntegrator uninterrupted(s, rhs);
    auto full = uninterrupted.start(0.0, {2.0, 0.0});
    ti::IntegrationState checkpoint;
    std::vector<std::vector<double>> fullOutputs;
    uninterrupted.integrate(full, schedule, {[&](const ti::IntegrationState& st, ti::OutputReason) {
                              fullOutputs.push_back(st.y);
                              if (st.nextOutput == 8) {
                                checkpoint = st;
                              }
                            }});
    ASSERT_EQ(checkpoint.time, 5.25);

    for (const bool throughRecord : {false, true}) {
      ti::IntegrationState resumed = throughRecord ? ti::fromRecord(ti::toRecord(checkpoint), "test") : checkpoint;
      ti::TimeIntegrator restarted(s, rhs); // a fresh integrator, as in a new process
      std::vector<std::vector<double>> restartOutputs;
      restarted.integrate(resumed, schedule,
                          {[&](const ti::IntegrationState& st, ti::OutputReason) { restartOutputs.push_back(st.y); }});
      // Outputs 8..16 again, no duplicate of output 7.
      ASSERT_EQ(restartOutputs.size(), fullOutputs.size() - 8) << method;
      for (std::size_t k = 0; k < restartOutputs.size(); ++k) {
        EXPECT_TRUE(sameBits(restartOutputs[k], fullOutputs[k + 8])) << "output " << k + 8;
      }
      EXPECT_TRUE(sameBits(resumed.y, full.y)) << method;
      EXPECT_TRUE(sameBits(resumed.time, full.time));
      EXPECT_TRUE(sameBits(resumed.proposedStep, full.proposedStep));
      expectSameStatistics(resumed.statistics, full.statistics);
    }
  }
}

TEST(Driver, RestartWithoutTheFsalDerivativeCostsOneEvaluationAndChangesNothingElse)
{
  const auto rhs = forcedVanDerPol();
  const auto s = adaptiveSettings("DormandPrince45", 6.0);
  ti::TimeIntegrator a(s, rhs);
  auto full = a.start(0.0, {2.0, 0.0});
  ti::IntegrationState checkpoint;
  a.integrate(full, {1.0, false}, {[&](const ti::IntegrationState& st, ti::OutputReason) {
                if (st.nextOutput == 4) {
                  checkpoint = st;
                }
              }});
  auto record = ti::toRecord(checkpoint);
  record.arrays.erase("first stage derivative");
  auto resumed = ti::fromRecord(record, "test");
  ti::TimeIntegrator b(s, rhs);
  b.integrate(resumed, {1.0, false}, {});
  EXPECT_TRUE(sameBits(resumed.y, full.y));
  EXPECT_EQ(resumed.statistics.acceptedSteps, full.statistics.acceptedSteps);
  EXPECT_EQ(resumed.statistics.rhsEvaluations, full.statistics.rhsEvaluations + 1);
}

TEST(Driver, RecordWithAMissingEntryNamesIt)
{
  auto record = ti::toRecord(ti::IntegrationState{});
  record.reals.erase("proposed step");
  try {
    ti::fromRecord(record, "run/checkpoint.h5");
    FAIL() << "an incomplete record was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'proposed step'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("run/checkpoint.h5"), std::string::npos) << e.what();
  }
}

TEST(Driver, SteadyStateIsDetectedByTheRateOfChange)
{
  const auto problem = ti::testing::exponentialDecay();
  auto s = adaptiveSettings("RKF45", 100.0);
  s.tolerance = 1e-10;
  s.steadyCriterion = ti::SteadyStateCriterion::MaxChangeRate;
  s.steadyTolerance = 1e-6;
  ti::TimeIntegrator integrator(s, problem.rhs);
  auto state = integrator.start(0.0, problem.y0);
  std::vector<ti::OutputReason> reasons;
  const auto stop = integrator.integrate(
      state, {1.0, false}, {[&](const ti::IntegrationState&, ti::OutputReason r) { reasons.push_back(r); }});
  EXPECT_EQ(stop, ti::StopReason::SteadyState);
  EXPECT_TRUE(state.steady);
  ASSERT_FALSE(reasons.empty());
  EXPECT_EQ(reasons.back(), ti::OutputReason::SteadyState);
  // |dy/dt| = |y| < 1e-6 at detection: a secant over one step of y' = -y overestimates
  // |y| by at most a factor e^h, so |y| is just below 1e-6 (and the run stopped long
  // before t = 100, at t ~ ln(1e6) = 13.8).
  EXPECT_LT(std::abs(state.y[0]), 1e-6);
  EXPECT_GT(std::abs(state.y[0]), 1e-7);
  EXPECT_LT(state.time, 20.0);
  // A steady state stays put: integrating again does nothing.
  const auto again = integrator.integrate(state, {1.0, false}, {});
  EXPECT_EQ(again, ti::StopReason::SteadyState);
}

TEST(Driver, SteadyStateIsDetectedByTheL2ChangeBetweenSteps)
{
  // Two decaying coordinates; L2 change per step below 1e-7 (the thesis's 2D criterion).
  const ti::RightHandSide rhs = [](double, const std::vector<double>& y, std::vector<double>& f) {
    f[0] = -y[0];
    f[1] = -2.0 * y[1];
  };
  auto s = adaptiveSettings("DormandPrince45", 100.0);
  s.steadyCriterion = ti::SteadyStateCriterion::L2Change;
  s.steadyTolerance = 1e-7;
  ti::TimeIntegrator integrator(s, rhs);
  auto state = integrator.start(0.0, {1.0, 1.0});
  double lastMeasure = 0.0;
  ti::StepReport report;
  while (!report.steady) {
    const std::vector<double> before = state.y;
    report = integrator.step(state, s.endTime);
    lastMeasure = std::hypot(state.y[0] - before[0], state.y[1] - before[1]);
    EXPECT_DOUBLE_EQ(report.steadyMeasure, lastMeasure); // hypot rounds differently
  }
  EXPECT_LT(lastMeasure, 1e-7);
  EXPECT_LT(state.time, 100.0);
}

TEST(Driver, NonFiniteRightHandSideNamesTheTimeAndKeepsTheLastAcceptedState)
{
  const ti::RightHandSide rhs = [](double t, const std::vector<double>& y, std::vector<double>& f) {
    f[0] = t < 0.5 ? -y[0] : std::numeric_limits<double>::quiet_NaN();
    f[1] = 1.0;
  };
  for (const std::string method : {"RKF45", "DormandPrince45", "RK4"}) {
    ti::TimeIntegrator integrator(adaptiveSettings(method, 1.0), rhs);
    auto state = integrator.start(0.0, {1.0, 0.0});
    ti::IntegrationState lastGood = state;
    try {
      for (;;) {
        lastGood = state;
        integrator.step(state, 1.0);
      }
    } catch (const core::NumericalError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("not finite at t = "), std::string::npos) << what;
      EXPECT_NE(what.find("last accepted"), std::string::npos) << what;
      std::printf("%s: %s\n", method.c_str(), what.c_str());
    }
    EXPECT_LT(state.time, 0.5);
    EXPECT_TRUE(sameBits(state.time, lastGood.time));
    EXPECT_TRUE(sameBits(state.y, lastGood.y));
    EXPECT_TRUE(sameBits(state.proposedStep, lastGood.proposedStep));
  }
}

TEST(Driver, NonFiniteInitialStateIsRejected)
{
  const auto problem = ti::testing::exponentialDecay();
  ti::TimeIntegrator integrator(adaptiveSettings("RKF45", 1.0), problem.rhs);
  EXPECT_THROW(integrator.start(0.0, {std::numeric_limits<double>::infinity()}), core::NumericalError);
}

TEST(Driver, StepSizeCollapseNamesTheStepAndTheTime)
{
  // A jump in the right-hand side at t = 0.5: the error estimate of a step straddling it
  // stays ~ jump * h, so a tolerance of 1e-8 needs h ~ 1e-8, below the floor 1e-4.
  const ti::RightHandSide rhs = [](double t, const std::vector<double>&, std::vector<double>& f) {
    f[0] = t < 0.5 ? 0.0 : 1.0;
  };
  for (const std::string method : {"RKF45", "DormandPrince45"}) {
    auto s = adaptiveSettings(method, 1.0);
    s.minimumStep = 1e-4;
    s.initialStep = 0.01;
    ti::TimeIntegrator integrator(s, rhs);
    auto state = integrator.start(0.0, {0.0});
    ti::IntegrationState lastGood = state;
    try {
      integrator.integrate(state, {}, {});
      FAIL() << "the step size did not collapse";
    } catch (const core::NumericalError& e) {
      const std::string what = e.what();
      std::printf("%s: %s\n", method.c_str(), what.c_str());
      EXPECT_NE(what.find("step size collapsed to "), std::string::npos) << what;
      EXPECT_NE(what.find("at t = "), std::string::npos) << what;
    }
    EXPECT_LE(state.time, 0.5);
    EXPECT_GT(state.time, 0.45);
    EXPECT_EQ(state.y[0], 0.0);
    EXPECT_GE(state.proposedStep, s.minimumStep);
  }
}

TEST(Driver, StageConstraintIsAppliedToEveryStage)
{
  // The constraint pins coordinate 0 (a tethered node) and removes the mean of
  // coordinates 1 and 2 (a fixed-height cell): y0 stays fixed exactly, the mean of y1
  // and y2 to rounding, while the unconstrained run moves both.
  const ti::RightHandSide rhs = [](double t, const std::vector<double>& y, std::vector<double>& f) {
    f[0] = 1.0 + y[1];
    f[1] = std::sin(t) + y[2];
    f[2] = 0.3 - y[1];
  };
  for (const std::string method : {"RKF45", "DormandPrince45", "RK4"}) {
    auto s = adaptiveSettings(method, 3.0);
    s.initialStep = method == "RK4" ? 0.01 : 1e-3;
    ti::TimeIntegrator freeIntegrator(s, rhs);
    auto unconstrained = freeIntegrator.start(0.0, {0.5, 1.0, 2.0});
    freeIntegrator.integrate(unconstrained, {}, {});
    EXPECT_GT(std::abs(unconstrained.y[0] - 0.5), 0.1);

    ti::TimeIntegrator constrained(s, rhs);
    std::int64_t calls = 0;
    constrained.setStageConstraint([&](double, const std::vector<double>&, std::vector<double>& f) {
      ++calls;
      f[0] = 0.0;
      const double mean = 0.5 * (f[1] + f[2]);
      f[1] -= mean;
      f[2] -= mean;
    });
    auto state = constrained.start(0.0, {0.5, 1.0, 2.0});
    constrained.integrate(state, {}, {});
    EXPECT_EQ(calls, state.statistics.rhsEvaluations);
    EXPECT_EQ(state.y[0], 0.5);
    // Linear invariants are kept by any Runge-Kutta method, up to rounding per step.
    EXPECT_NEAR(state.y[1] + state.y[2], 3.0, 1e-12);
    EXPECT_GT(std::abs(state.y[1] - 1.0), 0.01);
  }
}

TEST(Driver, InconsistentSettingsNameTheDeckKey)
{
  const auto problem = ti::testing::exponentialDecay();
  ti::TimeIntegrationSettings s;
  s.initialStep = 2.0;
  s.maximumStep = 1.0;
  try {
    ti::TimeIntegrator integrator(s, problem.rhs);
    FAIL() << "Initial step > Maximum step was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Initial step"), std::string::npos) << e.what();
  }
  s = {};
  s.method = "DormandPrince45";
  s.methodParameters.set("Local extrapolation", true);
  EXPECT_THROW(ti::TimeIntegrator(s, problem.rhs), core::InputError);
}
