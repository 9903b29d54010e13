// The stiff methods' Jacobian of the 2D capsule (VelocityJacobian2D.hpp): at an unstressed
// state (zero load) J~ is the exact derivative of the velocity for lambda = 1, so it must
// agree with differences of CapsuleModel2D::rightHandSide; its stage solves reach their
// target with the dense preconditioners in far fewer iterations than without; the tether
// holds in every J~ v and stage increment; and a stiff run of the cell converges at order 3.
#include "Tether2DTesting.hpp"

#include "capsula/testing/ConvergenceOrder.hpp"

#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/scene2d/CapsuleModel2D.hpp>
#include <capsula/scene2d/VelocityJacobian2D.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace capsula;
using namespace capsula::scene2d;
namespace {

// The model's keys and the time integration's, with `overrides` applied, validated.
Teuchos::ParameterList tether2dDeck(const std::vector<std::string>& overrides)
{
  Teuchos::ParameterList valid("tether2d");
  declareModelParameters2D(valid);
  timeint::declareTimeIntegrationParameters(valid.sublist("Time integration"));
  return scene2d::testing::deckWith(valid, overrides);
}

Teuchos::RCP<const Teuchos::Comm<int>> serial()
{
  return Teuchos::rcp(new Teuchos::SerialComm<int>);
}

CapsuleModel2D jacobianModelOf(const Teuchos::ParameterList& deck)
{
  return CapsuleModel2D(serial(), readCellSettings2D(deck.sublist("Cell")),
                        readFlowSettings2D(deck.sublist("Flow"), deck.sublist("Wall")),
                        scene2d::readContourDiscretisation2D(deck.sublist("Discretisation")),
                        operators::readSolverParameters(deck.sublist("Solver")));
}

std::vector<double> direction(std::size_t n)
{
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = std::sin(0.9 * static_cast<double>(i) + 0.4) + 0.5 * std::cos(0.07 * static_cast<double>(i));
  }
  return v;
}

double maxAbs(const std::vector<double>& v)
{
  double m = 0.0;
  for (const double x : v) {
    m = std::max(m, std::abs(x));
  }
  return m;
}

std::vector<double> applied(VelocityJacobian2D& jacobian, const std::vector<double>& v)
{
  std::vector<double> Jv(v.size());
  jacobian.apply(v.data(), Jv.data());
  return Jv;
}

} // namespace

// At the unstressed start the load vanishes, so what J~ leaves out (how the single layer
// moves with the nodes, times the load) vanishes too, and for lambda = 1 J~ v is the
// derivative of the velocity: (u(x + e v) - u(x - e v)) / 2e up to the differences' error.
// At e = 1e-6 (|v| <= 1.5, node spacing 0.2) the truncation, ~(e / 0.2)^2, and the
// round-off, ~1e-16 |u| / e against |J~ v| ~ 50, are below 1e-10 of |J~ v|, and so is the
// error of J~'s own differences (1e-10, the header); a wrong sign, factor 2 pi or flow term
// is an O(1) error. Free cell and tethered cell, in free space and above the wall; the free
// cells under a pulsatile shear rate at t = 0.5 of a period 2, amplitude 0.5 (k = 1.5: J~'s
// flow term is k(t) grad u_inf).
TEST(VelocityJacobian2D, IsTheDerivativeOfTheVelocityAtRest)
{
  for (const bool wall : {false, true}) {
    for (const bool tethered : {false, true}) {
      // J~'s single layer with the right-hand side's rule (6 Gauss-Legendre points, not 3).
      auto settings = std::vector<std::string>{"Cell/Number of points=32",
                                               "Cell/Aspect ratio=0.7",
                                               "Flow/Capillary number=0.05",
                                               "Solver/Stiff/Gauss-Legendre points=0",
                                               wall ? "Wall/Enabled=true" : "Wall/Enabled=false",
                                               wall ? "Cell/Lowest point height=0.1" : "Cell/Lowest point height=-1",
                                               wall ? "Tether/Enabled=true" : "Tether/Enabled=false"};
      if (!tethered) {
        settings.insert(settings.end(), {"Flow/Shear rate/Form=Pulsatile", "Flow/Shear rate/Amplitude=0.5",
                                         "Flow/Shear rate/Period=2"});
      }
      const double t = tethered ? 0.0 : 0.5;
      const auto deck = tether2dDeck(settings);
      CapsuleModel2D model = jacobianModelOf(deck);
      if (tethered) {
        model.tether(0); // node 0 held; the reference relabelled by 0: still unstressed
      }
      VelocityJacobian2D jacobian(model, serial(), deck);
      const std::vector<double> x = model.initialState();
      jacobian.linearise(t, x);
      const std::vector<double> v = direction(x.size());
      const std::vector<double> Jv = applied(jacobian, v);
      const double e = 1e-6;
      std::vector<double> plus(x), minus(x), up, um;
      for (std::size_t i = 0; i < x.size(); ++i) {
        plus[i] += e * v[i];
        minus[i] -= e * v[i];
      }
      model.rightHandSide(t, plus, up);
      model.rightHandSide(t, minus, um);
      double worst = 0.0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        worst = std::max(worst, std::abs(Jv[i] - (up[i] - um[i]) / (2 * e)));
      }
      EXPECT_LT(worst, 1e-8 * maxAbs(Jv)) << (wall ? "wall" : "free space") << (tethered ? ", tethered" : "");
      if (tethered) {
        EXPECT_EQ(Jv[0], 0.0);
        EXPECT_EQ(Jv[1], 0.0);
      }
    }
  }
}

// The stage solve of a stiff membrane (Ca = 0.01, 64 points above the wall, prestressed so
// that the normal modes are stiff too, shift 0.5: shift * rho ~ 400) reaches its RMS
// target (1e-8 of a right-hand side of RMS 0.8) with every preconditioner. Measured: 9
// iterations with the point single layer, 34 with the local mobility, 161 without.
TEST(VelocityJacobian2D, PreconditionedStageSolveConverges)
{
  int iterations[3] = {0, 0, 0};
  const std::vector<std::string> preconditioners{"Point single layer", "Local mobility", "None"};
  for (std::size_t p = 0; p < preconditioners.size(); ++p) {
    const auto deck = tether2dDeck({"Cell/Number of points=64", "Flow/Capillary number=0.01", "Cell/Prestress=0.1",
                                    "Cell/Lowest point height=0.05", "Solver/Stiff/Maximum iterations=1000",
                                    "Solver/Stiff/Preconditioner=" + preconditioners[p]});
    CapsuleModel2D model = jacobianModelOf(deck);
    VelocityJacobian2D jacobian(model, serial(), deck);
    const std::vector<double> x = model.initialState();
    jacobian.linearise(0.0, x);
    const double shift = 0.5;
    const std::vector<double> r = direction(x.size());
    std::vector<double> solution(r.size(), 0.0);
    const double target = 1e-8;
    const auto report = jacobian.solve(shift, r, solution, target);
    ASSERT_TRUE(report.converged) << preconditioners[p];
    // The true residual, recomputed: r - (x - shift J~ x).
    const std::vector<double> Jx = applied(jacobian, solution);
    double sum = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const double residual = r[i] - (solution[i] - shift * Jx[i]);
      sum += residual * residual;
    }
    // Flexible GMRES's residual estimate is that of its iterate: the true one to round-off.
    EXPECT_LT(std::sqrt(sum / static_cast<double>(r.size())), 1.01 * target) << preconditioners[p];
    iterations[p] = report.iterations;
  }
  EXPECT_LT(10 * iterations[0], iterations[2]) << iterations[0] << " vs " << iterations[2];
  EXPECT_LT(3 * iterations[1], iterations[2]) << iterations[1] << " vs " << iterations[2];
}

// The preconditioner's dense J~ (the point single layer times the load's differences, and
// the flow) stands for J~ itself: on smooth directions (modes 2 and 4 of the contour) they
// agree to 0.9% and 1.6% of |J~ v|; a wrong sign, factor or flow term in it would be an
// O(1) difference.
TEST(VelocityJacobian2D, ApproximateJacobianIsCloseOnSmoothDirections)
{
  const auto deck = tether2dDeck({"Cell/Number of points=64", "Flow/Capillary number=0.01", "Cell/Prestress=0.1",
                                  "Cell/Lowest point height=0.05"});
  CapsuleModel2D model = jacobianModelOf(deck);
  VelocityJacobian2D jacobian(model, serial(), deck);
  const std::vector<double> x = model.initialState();
  jacobian.linearise(0.0, x);
  const auto n = static_cast<Eigen::Index>(x.size());
  for (const int mode : {2, 4}) {
    std::vector<double> v(x.size());
    for (Eigen::Index i = 0; i < n / 2; ++i) {
      const double angle = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n / 2);
      v[2 * i] = std::cos(mode * angle);
      v[2 * i + 1] = 0.5 * std::sin(mode * angle + 0.3);
    }
    const std::vector<double> Jv = applied(jacobian, v);
    const Eigen::VectorXd approximate =
        jacobian.approximateJacobian().cast<double>() * Eigen::Map<const Eigen::VectorXd>(v.data(), n);
    double worst = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      worst = std::max(worst, std::abs(approximate[i] - Jv[static_cast<std::size_t>(i)]));
    }
    EXPECT_LT(worst, 0.05 * maxAbs(Jv)) << "mode " << mode;
  }
}

// The tether is part of J~: the tethered node's rows of J~ v and of its dense stand-in are
// zero, so a stage increment whose right-hand side holds the node keeps it held.
TEST(VelocityJacobian2D, TetheredNodeStaysHeldInTheStageSolve)
{
  const auto deck = tether2dDeck({"Cell/Number of points=48", "Flow/Capillary number=0.01", "Cell/Prestress=0.1"});
  CapsuleModel2D model = jacobianModelOf(deck);
  model.tether(5);
  VelocityJacobian2D jacobian(model, serial(), deck);
  std::vector<double> x = model.initialState();
  std::rotate(x.begin(), x.begin() + 10, x.end()); // node 5 of the free cell is node 0 now
  jacobian.linearise(0.0, x);
  std::vector<double> r = direction(x.size());
  const std::vector<double> Jr = applied(jacobian, r);
  EXPECT_EQ(Jr[0], 0.0);
  EXPECT_EQ(Jr[1], 0.0);
  EXPECT_EQ(jacobian.approximateJacobian().row(0).norm(), 0.0f);
  EXPECT_EQ(jacobian.approximateJacobian().row(1).norm(), 0.0f);
  EXPECT_GT(maxAbs(Jr), 1.0);
  r[0] = r[1] = 0.0;
  std::vector<double> solution(r.size(), 0.0);
  const auto report = jacobian.solve(0.5, r, solution, 1e-10);
  ASSERT_TRUE(report.converged);
  // Row 0 of W is the identity: the solution's node 0 is r's, zero, up to GMRES round-off.
  EXPECT_LT(std::abs(solution[0]) + std::abs(solution[1]), 1e-14 * maxAbs(solution));
}

// ROS34PW2 with fixed steps on a stiff 32-point cell (Ca = 0.01 near the wall: the
// membrane's fastest rate is ~400 against steps of 0.025-0.0125, so h rho ~ 5-10): the
// error at k t = 0.2 against a run with a quarter of the smallest step falls at order 3
// (within 0.2; the stiff modes, damped by the L-stable method, do not spoil it).
TEST(VelocityJacobian2D, StiffCellRunConvergesAtOrderThree)
{
  const auto deck = tether2dDeck({"Cell/Number of points=32", "Flow/Capillary number=0.01", "Cell/Prestress=0.1",
                                  "Cell/Lowest point height=0.1", "Time integration/Method=ROS34PW2",
                                  "Time integration/Tolerance=1e-9"}); // stage solves to 1e-11 RMS
  const auto run = [&](int steps) {
    CapsuleModel2D model = jacobianModelOf(deck);
    auto settings = timeint::timeIntegrationSettings(deck.sublist("Time integration"));
    settings.adaptive = false;
    settings.initialStep = 0.2 / steps;
    timeint::TimeIntegrator integrator(settings, [&model](double, const std::vector<double>& y,
                                                          std::vector<double>& u) { model.rightHandSide(0.0, y, u); });
    integrator.setLinearisedSystem(std::make_shared<VelocityJacobian2D>(model, serial(), deck));
    auto state = integrator.start(0.0, model.initialState());
    while (state.time < 0.2) {
      integrator.step(state, 0.2);
    }
    return state.y;
  };
  const std::vector<double> reference = run(64);
  const std::vector<int> counts{8, 12, 16};
  std::vector<double> errors;
  for (const int n : counts) {
    const std::vector<double> y = run(n);
    double e = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      e = std::max(e, std::abs(y[i] - reference[i]));
    }
    errors.push_back(e);
  }
  EXPECT_NEAR(capsula::testing::fittedOrder(counts, errors), 3.0, 0.2) << errors[0] << " " << errors[2];
}

// GMRES needs a linear operator: J~ (a difference quotient of the load) is linear to the
// differences' error, ~1e-12 of |J~ v| (measured 1e-11 on a combination of a rough and a
// 1000 times smaller smooth direction); second-order differences at their best step leave
// 1e-10, which stalled unpreconditioned GMRES above 1e-8.
TEST(VelocityJacobian2D, IsLinear)
{
  const auto deck = tether2dDeck({"Cell/Number of points=64", "Flow/Capillary number=0.01", "Cell/Prestress=0.1",
                                  "Cell/Lowest point height=0.05"});
  CapsuleModel2D model = jacobianModelOf(deck);
  VelocityJacobian2D jacobian(model, serial(), deck);
  const std::vector<double> x = model.initialState();
  jacobian.linearise(0.0, x);
  const std::vector<double> a = direction(x.size());
  std::vector<double> b(x.size()), sum(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    b[i] = 1e-3 * std::cos(0.3 * static_cast<double>(i));
    sum[i] = 0.7 * a[i] + 30.0 * b[i];
  }
  const auto Ja = applied(jacobian, a), Jb = applied(jacobian, b), Js = applied(jacobian, sum);
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    worst = std::max(worst, std::abs(Js[i] - 0.7 * Ja[i] - 30.0 * Jb[i]));
  }
  EXPECT_LT(worst, 1e-10 * maxAbs(Js));
}
