// Fixed-step convergence orders and adaptive error control.
#include "TestProblems.hpp"
#include "capsula/testing/ConvergenceOrder.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace ti = capsula::timeint;
using ti::testing::TestProblem;

namespace {

/// Global error at t = endTime after `steps` fixed steps.
double fixedStepError(const std::string& method, const TestProblem& problem, int steps, double endTime)
{
  ti::TimeIntegrationSettings s;
  s.method = method;
  s.adaptive = false;
  s.endTime = endTime;
  s.initialStep = endTime / steps;
  ti::TimeIntegrator integrator(s, problem.rhs);
  auto state = integrator.start(0.0, problem.y0);
  integrator.integrate(state, {}, {});
  EXPECT_EQ(state.time, endTime);
  EXPECT_EQ(state.statistics.acceptedSteps, steps);
  return ti::testing::maxError(state.y, problem.exact(endTime));
}

void expectFixedStepOrder(const std::string& method, int expectedOrder)
{
  const double endTime = 2.0;
  for (const auto& problem : {ti::testing::exponentialDecay(), ti::testing::cosine(), ti::testing::rotation()}) {
    // 4th-order methods need h <= 1/8 to be asymptotic on y' = cos t; 5th-order ones
    // would reach round-off (1e-15) at h = 1/64.
    const int coarsest = expectedOrder == 4 ? 16 : 8;
    std::vector<double> h, error;
    for (int steps = coarsest; steps <= 8 * coarsest; steps *= 2) {
      h.push_back(endTime / steps);
      error.push_back(fixedStepError(method, problem, steps, endTime));
    }
    const double order = capsula::testing::logLogSlope(h, error);
    std::printf("%-16s %-14s errors %.3e %.3e %.3e %.3e  order %.3f\n", method.c_str(), problem.name.c_str(), error[0],
                error[1], error[2], error[3], order);
    // In the asymptotic range the observed slope is within 0.2 of the order (a wrong
    // coefficient drops it by >= 1).
    EXPECT_NEAR(order, expectedOrder, 0.2) << method << " on " << problem.name;
  }
}

struct AdaptiveRun {
  double error;
  ti::IntegrationStatistics statistics;
};

AdaptiveRun adaptiveRun(const std::string& method, double tolerance)
{
  const auto problem = ti::testing::relaxation();
  ti::TimeIntegrationSettings s;
  s.method = method;
  s.tolerance = tolerance;
  s.endTime = 5.0;
  s.initialStep = 1e-3;
  s.maximumStep = 1.0;
  ti::TimeIntegrator integrator(s, problem.rhs);
  auto state = integrator.start(0.0, problem.y0);
  integrator.integrate(state, {}, {});
  return {ti::testing::maxError(state.y, problem.exact(s.endTime)), state.statistics};
}

void expectErrorFollowsTolerance(const std::string& method)
{
  std::printf("%s on y' = -5 (y - cos t), t in [0, 5]\n", method.c_str());
  std::printf("  tolerance   global error  error/tol  accepted rejected rhs-evals\n");
  std::vector<double> tolerances, errors;
  for (double tol = 1e-3; tol >= 0.9e-11; tol /= 10.0) {
    const AdaptiveRun run = adaptiveRun(method, tol);
    std::printf("  %9.1e  %12.3e  %9.3f  %8lld %8lld %9lld\n", tol, run.error, run.error / tol,
                static_cast<long long>(run.statistics.acceptedSteps),
                static_cast<long long>(run.statistics.rejectedSteps),
                static_cast<long long>(run.statistics.rhsEvaluations));
    if (!errors.empty()) {
      EXPECT_LT(run.error, errors.back()) << "error must decrease with the tolerance, tol " << tol;
    }
    // The global error stays within two decades of the tolerance: error control works
    // (without it the error would not follow tol at all).
    EXPECT_LT(run.error, 30.0 * tol);
    EXPECT_GT(run.error, 1e-3 * tol);
    tolerances.push_back(tol);
    errors.push_back(run.error);
  }
  // Error ~ tol^p with p near 1 (a local error per step held near tol, and the step
  // count growing like tol^(-1/5)).
  const double slope = capsula::testing::logLogSlope(tolerances, errors);
  std::printf("  fitted slope d log(error) / d log(tol) = %.3f\n", slope);
  EXPECT_GT(slope, 0.6);
  EXPECT_LT(slope, 1.3);
}

} // namespace

TEST(Convergence, RKF45FourthOrderSolutionConvergesAtOrder4)
{
  expectFixedStepOrder("RKF45", 4);
}

TEST(Convergence, DormandPrince45ConvergesAtOrder5)
{
  expectFixedStepOrder("DormandPrince45", 5);
}

TEST(Convergence, ClassicalRK4ConvergesAtOrder4)
{
  expectFixedStepOrder("RK4", 4);
}

TEST(Convergence, RKF45WithLocalExtrapolationConvergesAtOrder5)
{
  const auto problem = ti::testing::rotation();
  std::vector<double> h, error;
  for (int steps : {8, 16, 32, 64}) {
    ti::TimeIntegrationSettings s;
    s.adaptive = false;
    s.methodParameters.set("Local extrapolation", true);
    s.endTime = 2.0;
    s.initialStep = s.endTime / steps;
    ti::TimeIntegrator integrator(s, problem.rhs);
    auto state = integrator.start(0.0, problem.y0);
    integrator.integrate(state, {}, {});
    h.push_back(s.initialStep);
    error.push_back(ti::testing::maxError(state.y, problem.exact(s.endTime)));
  }
  EXPECT_NEAR(capsula::testing::logLogSlope(h, error), 5.0, 0.2);
}

TEST(AdaptiveControl, RKF45GlobalErrorFollowsTheTolerance)
{
  expectErrorFollowsTolerance("RKF45");
}

TEST(AdaptiveControl, DormandPrince45GlobalErrorFollowsTheTolerance)
{
  expectErrorFollowsTolerance("DormandPrince45");
}

TEST(AdaptiveControl, RightHandSideEvaluationsAreCountedPerStage)
{
  const auto problem = ti::testing::relaxation();
  for (const std::string method : {"RKF45", "DormandPrince45"}) {
    ti::TimeIntegrationSettings s;
    s.method = method;
    s.tolerance = 1e-8;
    s.endTime = 5.0;
    s.initialStep = 0.5; // too large: forces some rejections at the start
    ti::TimeIntegrator integrator(s, problem.rhs);
    auto state = integrator.start(0.0, problem.y0);
    integrator.integrate(state, {}, {});
    const auto& st = state.statistics;
    EXPECT_GT(st.rejectedSteps, 0);
    if (method == "RKF45") {
      // 6 stages per accepted step; a retry reuses k1 (5 new stages).
      EXPECT_EQ(st.rhsEvaluations, 6 * st.acceptedSteps + 5 * st.rejectedSteps);
    } else {
      // FSAL: one evaluation to start, then 6 per attempt.
      EXPECT_EQ(st.rhsEvaluations, 1 + 6 * (st.acceptedSteps + st.rejectedSteps));
    }
    EXPECT_LE(st.smallestStep, st.lastStep);
    EXPECT_GE(st.largestStep, st.lastStep);
  }
}
