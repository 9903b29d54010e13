// The Rosenbrock-W methods (RosenbrockTableau.hpp, RosenbrockMethod.cpp): their
// coefficients' order conditions, L-stability, observed orders on a stiff linear system
// and, as W-methods, with a wrong Jacobian; adaptive steps, failure handling and restart.
#include "TestProblems.hpp"

#include "capsula/testing/ConvergenceOrder.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/timeint/DenseLinearisedSystem.hpp"
#include "capsula/timeint/RosenbrockTableau.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace ti = capsula::timeint;
using capsula::testing::logLogSlope;
using ti::testing::maxError;

namespace {

double at(const std::vector<double>& matrix, int s, int i, int j)
{
  return matrix[static_cast<std::size_t>(i * s + j)];
}

// Order conditions of a Rosenbrock method in the standard form up to order 3 (Hairer &
// Wanner, Solving ODEs II, Table IV.7.1), with beta_ij = alpha_ij + gamma_ij (i > j) and
// beta_i' = sum_{j<i} beta_ij; returns the residuals of the conditions for orders 1..3.
std::vector<double> orderConditionResiduals(const ti::RosenbrockTableau& t)
{
  const int s = t.stages;
  std::vector<double> alphaSum(static_cast<std::size_t>(s), 0.0), betaSum(static_cast<std::size_t>(s), 0.0);
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < i; ++j) {
      alphaSum[static_cast<std::size_t>(i)] += at(t.alpha, s, i, j);
      betaSum[static_cast<std::size_t>(i)] += at(t.alpha, s, i, j) + at(t.gammaOffDiagonal, s, i, j);
    }
  }
  const double g = t.gamma;
  double c1 = -1.0, c2 = -(0.5 - g), c3a = -1.0 / 3.0, c3b = -(1.0 / 6.0 - g + g * g);
  for (int i = 0; i < s; ++i) {
    const double b = t.b[static_cast<std::size_t>(i)];
    c1 += b;
    c2 += b * betaSum[static_cast<std::size_t>(i)];
    c3a += b * alphaSum[static_cast<std::size_t>(i)] * alphaSum[static_cast<std::size_t>(i)];
    for (int j = 0; j < i; ++j) {
      c3b += b * (at(t.alpha, s, i, j) + at(t.gammaOffDiagonal, s, i, j)) * betaSum[static_cast<std::size_t>(j)];
    }
  }
  return {c1, c2, c3a, c3b};
}

// y' = A y, A = [[-2, 1], [998, -999]]: eigenvalues -1 (eigenvector (1, 1)) and -1000
// (eigenvector (1, -998)). From y0 = (1, 1) + 1e-3 (1, -998) the fast mode dies at once
// and the slow one sets the accuracy.
const double kStiff[4] = {-2.0, 1.0, 998.0, -999.0};

void stiffLinearRhs(double, const std::vector<double>& y, std::vector<double>& f)
{
  f[0] = kStiff[0] * y[0] + kStiff[1] * y[1];
  f[1] = kStiff[2] * y[0] + kStiff[3] * y[1];
}

std::vector<double> stiffLinearExact(double t)
{
  const double slow = std::exp(-t), fast = 1e-3 * std::exp(-1000.0 * t);
  return {slow + fast, slow - 998.0 * fast};
}

std::shared_ptr<ti::DenseLinearisedSystem> exactStiffJacobian()
{
  return std::make_shared<ti::DenseLinearisedSystem>(
      [](double, const std::vector<double>&, std::vector<double>& J) { J.assign(kStiff, kStiff + 4); });
}

ti::TimeIntegrationSettings fixedSteps(const std::string& method, double h, double end)
{
  ti::TimeIntegrationSettings s;
  s.method = method;
  s.adaptive = false;
  s.initialStep = h;
  s.endTime = end;
  return s;
}

std::vector<double> integrateTo(ti::TimeIntegrator& integrator, std::vector<double> y0, double end)
{
  auto state = integrator.start(0.0, std::move(y0));
  while (state.time < end) {
    integrator.step(state, end);
  }
  return state.y;
}

// A nonlinear non-stiff pendulum-like problem with a known Jacobian, for the W property.
void pendulumRhs(double, const std::vector<double>& y, std::vector<double>& f)
{
  f[0] = y[1];
  f[1] = -std::sin(y[0]) + 0.1 * y[1] * y[0];
}

void pendulumJacobian(double, const std::vector<double>& y, std::vector<double>& J)
{
  J = {0.0, 1.0, -std::cos(y[0]) + 0.1 * y[1], 0.1 * y[0]};
}

} // namespace

// The published coefficients satisfy the order conditions to round-off (a mistyped digit
// leaves a residual of its own size), ROS34PW2 up to order 3, ROS2 up to order 2.
TEST(Rosenbrock, CoefficientsSatisfyTheOrderConditions)
{
  const auto r34 = orderConditionResiduals(ti::ros34pw2());
  for (std::size_t k = 0; k < r34.size(); ++k) {
    EXPECT_NEAR(r34[k], 0.0, 1e-14) << "ROS34PW2 condition " << k;
  }
  const auto r2 = orderConditionResiduals(ti::ros2());
  EXPECT_NEAR(r2[0], 0.0, 1e-15);
  EXPECT_NEAR(r2[1], 0.0, 1e-15);
  EXPECT_GT(std::abs(r2[2]) + std::abs(r2[3]), 1e-3); // and not order 3
  // The embedded solution of ROS34PW2 has order 2: its first two conditions hold.
  auto embedded = ti::ros34pw2();
  embedded.b = embedded.bEmbedded;
  const auto re = orderConditionResiduals(embedded);
  EXPECT_NEAR(re[0], 0.0, 1e-14);
  EXPECT_NEAR(re[1], 0.0, 1e-14);
}

// L-stability: R(z) -> 0 as z -> -infinity, |R| <= 1 on the imaginary axis (A-stability,
// sampled), and R(z) = exp(z) + O(z^4) near 0 for order 3.
TEST(Rosenbrock, StabilityFunctionIsLStable)
{
  for (const auto& t : {ti::ros34pw2(), ti::ros2()}) {
    EXPECT_LT(std::abs(ti::rosenbrockStabilityFunction(t, -1e8)), 1e-6) << t.name;
    // R(z) ~ 2.87 / z for ROS34PW2 (~1 / z^2 for ROS2): the stiffer the mode, the more damped.
    EXPECT_LT(std::abs(ti::rosenbrockStabilityFunction(t, -1e3)), 3e-3) << t.name;
    for (double x = -1.0; x > -1e6; x *= 1.7) {
      EXPECT_LE(std::abs(ti::rosenbrockStabilityFunction(t, x)), 1.0) << t.name << " at " << x;
    }
  }
  const auto t = ti::ros34pw2();
  const double z = 1e-2;
  EXPECT_LT(std::abs(ti::rosenbrockStabilityFunction(t, -z) - std::exp(-z)), 1e-9); // O(z^4) ~ 1e-8 / 24
}

// A stiff mode is damped in one step whatever its rate: one step of h = 1 on y' = -rate y.
TEST(Rosenbrock, OneStepDampsAStiffMode)
{
  for (const std::string method : {"ROS34PW2", "ROS2"}) {
    for (const double rate : {1e3, 1e6, 1e9}) {
      ti::TimeIntegrator integrator(
          fixedSteps(method, 1.0, 1.0),
          [rate](double, const std::vector<double>& y, std::vector<double>& f) { f[0] = -rate * y[0]; });
      integrator.setLinearisedSystem(std::make_shared<ti::DenseLinearisedSystem>(
          [rate](double, const std::vector<double>&, std::vector<double>& J) { J[0] = -rate; }));
      const auto y = integrateTo(integrator, {1.0}, 1.0);
      // |R(-rate)| ~ 3 / rate for ROS34PW2 and smaller for ROS2: far below 1 for any rate.
      EXPECT_LT(std::abs(y[0]), 10.0 / rate) << method << " rate " << rate;
    }
  }
}

// Fixed steps h = 0.1 ... 0.0125 on the stiff linear system, h * 1000 = 100 ... 12.5, far
// outside any explicit method's stability region: the error falls at the design order.
TEST(Rosenbrock, ObservedOrderOnAStiffLinearSystem)
{
  for (const auto& [method, design] : {std::pair{std::string("ROS34PW2"), 3.0}, std::pair{std::string("ROS2"), 2.0}}) {
    std::vector<double> steps, errors;
    for (const double h : {0.1, 0.05, 0.025, 0.0125}) {
      ti::TimeIntegrator integrator(fixedSteps(method, h, 2.0), stiffLinearRhs);
      integrator.setLinearisedSystem(exactStiffJacobian());
      const std::vector<double> y0 = stiffLinearExact(0.0);
      steps.push_back(h);
      errors.push_back(maxError(integrateTo(integrator, y0, 2.0), stiffLinearExact(2.0)));
    }
    EXPECT_NEAR(logLogSlope(steps, errors), design, 0.2) << method;
  }
}

// A W-method keeps its order with any J~: the exact Jacobian, none at all (J~ = 0, an
// explicit method then) and a wrong one give order 3 on a smooth nonlinear problem.
TEST(Rosenbrock, KeepsItsOrderWithAnApproximateJacobian)
{
  const std::vector<ti::DenseLinearisedSystem::JacobianFunction> jacobians{
      pendulumJacobian, [](double, const std::vector<double>&, std::vector<double>& J) { J.assign(4, 0.0); },
      [](double t, const std::vector<double>& y, std::vector<double>& J) {
        pendulumJacobian(t, y, J);
        J = {0.5 * J[0] + 0.3, 0.5 * J[1], 0.5 * J[2], 0.5 * J[3] - 0.2};
      }};
  for (std::size_t k = 0; k < jacobians.size(); ++k) {
    const auto reference = [&] {
      ti::TimeIntegrator fine(fixedSteps("ROS34PW2", 1.0 / 2048, 1.0), pendulumRhs);
      fine.setLinearisedSystem(std::make_shared<ti::DenseLinearisedSystem>(pendulumJacobian));
      return integrateTo(fine, {1.0, 0.3}, 1.0);
    }();
    std::vector<double> steps, errors;
    for (const int n : {16, 32, 64, 128}) {
      ti::TimeIntegrator integrator(fixedSteps("ROS34PW2", 1.0 / n, 1.0), pendulumRhs);
      integrator.setLinearisedSystem(std::make_shared<ti::DenseLinearisedSystem>(jacobians[k]));
      steps.push_back(1.0 / n);
      errors.push_back(maxError(integrateTo(integrator, {1.0, 0.3}, 1.0), reference));
    }
    EXPECT_NEAR(logLogSlope(steps, errors), 3.0, 0.2) << "Jacobian " << k;
  }
}

// Adaptive ROS34PW2 on the stiff system: the error at the end is of the order of the
// tolerance and the steps grow with the slow mode's time scale, not the fast one's.
TEST(Rosenbrock, AdaptiveStepsFollowAccuracyNotStiffness)
{
  ti::TimeIntegrationSettings s;
  s.method = "ROS34PW2";
  s.tolerance = 1e-6;
  s.initialStep = 1e-4;
  s.endTime = 5.0;
  ti::TimeIntegrator integrator(s, stiffLinearRhs);
  integrator.setLinearisedSystem(exactStiffJacobian());
  auto state = integrator.start(0.0, stiffLinearExact(0.0));
  while (state.time < s.endTime) {
    integrator.step(state, s.endTime);
  }
  // Accumulated local errors of 1e-6: the global error stays within a few tolerances.
  EXPECT_LT(maxError(state.y, stiffLinearExact(5.0)), 1e-5);
  // RKF45 under its stability limit needs 5 / (0.8 * 3.02 / 1000) = 2070 steps; the 3(2)
  // pair's error estimate (~h^3) allows 0.02-0.09 here, about 280 steps.
  EXPECT_LT(state.statistics.acceptedSteps, 2070 / 5);
  EXPECT_EQ(state.statistics.stiffSteps, state.statistics.acceptedSteps);
  EXPECT_EQ(state.statistics.linearSolves, 4 * (state.statistics.acceptedSteps + state.statistics.rejectedSteps));
  EXPECT_GT(state.statistics.largestStep, 0.05);
}

// The finite-difference Jacobian agrees with the exact one to the accuracy of forward
// differences (~1e-7 relative), constraint included.
TEST(Rosenbrock, FiniteDifferenceJacobian)
{
  auto system = ti::DenseLinearisedSystem::finiteDifferences(
      pendulumRhs, [](double, const std::vector<double>&, std::vector<double>& f) { f[1] *= 2.0; });
  system.linearise(0.0, {0.7, -0.4});
  std::vector<double> exact(4);
  pendulumJacobian(0.0, {0.7, -0.4}, exact);
  exact[2] *= 2.0;
  exact[3] *= 2.0;
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(system.jacobian()[static_cast<std::size_t>(k)], exact[static_cast<std::size_t>(k)], 1e-6) << k;
  }
}

namespace {

// Solves exactly while shift <= limit, fails above it (as a Krylov solver whose iteration
// cap is too small for large steps would).
class SolverFailingAboveShift final : public ti::LinearisedSystem {
public:
  explicit SolverFailingAboveShift(double limit) : limit_(limit), dense_(exactStiffJacobian()) {}
  void linearise(double t, const std::vector<double>& y) override { dense_->linearise(t, y); }
  ti::LinearSolveReport solve(double shift, const std::vector<double>& r, std::vector<double>& x,
                              double residual) override
  {
    if (shift > limit_) {
      return {false, 50, 1.0};
    }
    return dense_->solve(shift, r, x, residual);
  }
  std::string settingsHint() const override { return "(raise 'Solver/Stiff/Maximum iterations')"; }

private:
  double limit_;
  std::shared_ptr<ti::DenseLinearisedSystem> dense_;
};

} // namespace

// A stage solve that does not converge rejects the step, which is retried with a quarter
// of it: the run goes on with steps whose solves converge.
TEST(Rosenbrock, FailedSolveRejectsAndShrinksTheStep)
{
  ti::TimeIntegrationSettings s;
  s.method = "ROS34PW2";
  s.tolerance = 1e-4;
  s.initialStep = 0.4;
  s.endTime = 1.0;
  ti::TimeIntegrator integrator(s, stiffLinearRhs);
  const double limit = 0.05; // shift = h gamma: steps up to 0.115 solve
  integrator.setLinearisedSystem(std::make_shared<SolverFailingAboveShift>(limit));
  auto state = integrator.start(0.0, stiffLinearExact(0.0));
  const auto report = integrator.step(state, 1.0);
  EXPECT_GE(report.rejectedAttempts, 1);
  EXPECT_LE(report.stepSize * ti::ros34pw2().gamma, limit);
  EXPECT_GE(state.statistics.failedLinearSolves, 1);
}

// When the solves fail for every step down to the minimum, the run stops with the last
// accepted state and a message naming the solver's keys.
TEST(Rosenbrock, SolvesFailingDownToTheMinimumStepStopTheRun)
{
  ti::TimeIntegrationSettings s;
  s.method = "ROS34PW2";
  s.initialStep = 0.1;
  s.minimumStep = 1e-3;
  s.endTime = 1.0;
  ti::TimeIntegrator integrator(s, stiffLinearRhs);
  integrator.setLinearisedSystem(std::make_shared<SolverFailingAboveShift>(0.0));
  auto state = integrator.start(0.0, stiffLinearExact(0.0));
  const std::vector<double> before = state.y;
  try {
    integrator.step(state, 1.0);
    FAIL() << "expected a NumericalError";
  } catch (const capsula::core::NumericalError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Solver/Stiff/Maximum iterations"), std::string::npos) << message;
    EXPECT_NE(message.find("Minimum step"), std::string::npos) << message;
  }
  EXPECT_EQ(state.y, before);
  EXPECT_EQ(state.time, 0.0);
  EXPECT_EQ(state.proposedStep, 0.1);
}

// A right-hand side that finds a stage state outside the model (as a folded membrane is)
// rejects the attempt, which is retried with half the step, and the rejection is counted
// as the domain's; an attempt whose stages stay inside is accepted.
TEST(Rosenbrock, StageOutsideTheDomainRejectsAndHalvesTheStep)
{
  ti::TimeIntegrationSettings s;
  s.method = "ROS34PW2";
  s.tolerance = 1e-4;
  s.initialStep = 0.04;
  s.endTime = 1.0;
  std::vector<double> outsideAt; // the stage times that were outside
  ti::TimeIntegrator integrator(s, [&](double t, const std::vector<double>& y, std::vector<double>& f) {
    if (t > 0.0 && outsideAt.size() < 2) { // the first two attempts' second stages
      outsideAt.push_back(t);
      throw ti::StateOutsideDomain("stage outside");
    }
    stiffLinearRhs(t, y, f);
  });
  integrator.setLinearisedSystem(exactStiffJacobian());
  auto state = integrator.start(0.0, stiffLinearExact(0.0));
  const auto report = integrator.step(state, 1.0);
  ASSERT_EQ(outsideAt.size(), 2u);
  EXPECT_EQ(outsideAt[1], 0.5 * outsideAt[0]); // the second attempt is half the first
  EXPECT_EQ(state.statistics.rejectedOutsideDomain, 2);
  EXPECT_GE(report.rejectedAttempts, 2); // and the error control's, if any
  EXPECT_LE(report.stepSize, 0.01);
  EXPECT_GT(state.time, 0.0);
}

// A stiff method without a LinearisedSystem is refused with a message naming the key.
TEST(Rosenbrock, StiffMethodWithoutJacobianIsRefused)
{
  ti::TimeIntegrationSettings s;
  s.method = "ROS34PW2";
  ti::TimeIntegrator integrator(s, stiffLinearRhs);
  auto state = integrator.start(0.0, {1.0, 1.0});
  try {
    integrator.step(state, 1.0);
    FAIL() << "expected an InputError";
  } catch (const capsula::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Time integration/Method ROS34PW2"), std::string::npos) << e.what();
  }
}

// Continuing from a copy of the state (or its checkpoint record) repeats the run bit for bit.
TEST(Rosenbrock, RestartIsBitForBit)
{
  ti::TimeIntegrationSettings s;
  s.method = "ROS34PW2";
  s.tolerance = 1e-7;
  s.initialStep = 1e-3;
  s.endTime = 3.0;
  const auto run = [&](ti::IntegrationState state) {
    ti::TimeIntegrator integrator(s, stiffLinearRhs);
    integrator.setLinearisedSystem(exactStiffJacobian());
    while (state.time < s.endTime) {
      integrator.step(state, s.endTime);
    }
    return state;
  };
  ti::TimeIntegrator integrator(s, stiffLinearRhs);
  integrator.setLinearisedSystem(exactStiffJacobian());
  auto state = integrator.start(0.0, stiffLinearExact(0.0));
  for (int k = 0; k < 17; ++k) {
    integrator.step(state, s.endTime);
  }
  const auto restarted = run(ti::fromRecord(ti::toRecord(state), "test"));
  const auto uninterrupted = run(state);
  EXPECT_EQ(restarted.y, uninterrupted.y);
  EXPECT_EQ(restarted.statistics.acceptedSteps, uninterrupted.statistics.acceptedSteps);
  EXPECT_EQ(restarted.statistics.linearSolves, uninterrupted.statistics.linearSolves);
  EXPECT_EQ(restarted.statistics.stiffSteps, uninterrupted.statistics.stiffSteps);
}
