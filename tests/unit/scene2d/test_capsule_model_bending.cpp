// Cell/Bending modulus in the 2D cell model: the deck keys, the membrane it builds (bending
// only when asked), relaxation without flow (a circle stays at rest, a perturbed circle goes
// back towards a circle with its energy falling), the stiff Jacobian at a bending-free rest
// state, and ROS34PW2's order with the bending load.
#include "Tether2DTesting.hpp"

#include "capsula/testing/ConvergenceOrder.hpp"

#include <capsula/contour/InitialShapes.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/scene2d/CapsuleModel2D.hpp>
#include <capsula/scene2d/VelocityJacobian2D.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace capsula;
using namespace capsula::scene2d;

namespace {

Teuchos::ParameterList bendingDeck(const std::vector<std::string>& overrides)
{
  Teuchos::ParameterList valid("tether2d");
  declareModelParameters2D(valid);
  timeint::declareTimeIntegrationParameters(valid.sublist("Time integration"));
  // Bending needs the not-a-knot tether ends (the natural ones are refused); the free
  // cells here never tether, so the choice changes nothing else.
  std::vector<std::string> all = {"Cell/Tether spline ends=NotAKnot"};
  all.insert(all.end(), overrides.begin(), overrides.end());
  return scene2d::testing::deckWith(valid, all);
}

Teuchos::RCP<const Teuchos::Comm<int>> bendingComm()
{
  return Teuchos::rcp(new Teuchos::SerialComm<int>);
}

CapsuleModel2D bendingModelOf(const Teuchos::ParameterList& deck)
{
  return CapsuleModel2D(bendingComm(), readCellSettings2D(deck.sublist("Cell")),
                        readFlowSettings2D(deck.sublist("Flow"), deck.sublist("Wall")),
                        scene2d::readContourDiscretisation2D(deck.sublist("Discretisation")),
                        operators::readSolverParameters(deck.sublist("Solver")));
}

double largest(const std::vector<double>& v)
{
  double m = 0.0;
  for (const double x : v) {
    m = std::max(m, std::abs(x));
  }
  return m;
}

/// Node velocities of the model's cell in fluid at rest (no shear): the membrane's own
/// relaxation, u = -c SL[Delta f] (lambda = 1).
class RelaxationWithoutFlow {
public:
  explicit RelaxationWithoutFlow(CapsuleModel2D& model)
      : model_(model),
        velocity_(scene2d::makeInterfaceVelocity2D(model.flow().domain.hasLowerWall(), bendingComm(),
                                                   model.numberOfNodes(), model.discretisation(),
                                                   operators::SolverParameters{}))
  {
    conditions_ = model.flow().conditions;
    conditions_.background = scene2d::LinearFlow2D{};
  }
  std::vector<double> operator()(const std::vector<double>& y)
  {
    const contour::Contour c = model_.contour(y);
    const scene2d::MembraneState2D membrane = model_.membrane(c);
    const scene2d::ContourLoad2D load = [&membrane](const contour::ContourPoint& p, int k, double t) {
      return membrane.loadAt(p, k, t);
    };
    return velocity_->nodeVelocities(c, load, conditions_, {}).velocities;
  }

private:
  CapsuleModel2D& model_;
  std::unique_ptr<scene2d::InterfaceVelocity2D> velocity_;
  scene2d::FlowConditions2D conditions_;
};

/// max r - min r about the centroid of the nodes.
double radialSpread(const std::vector<double>& y)
{
  const Eigen::Map<const Eigen::Matrix2Xd> x(y.data(), 2, static_cast<Eigen::Index>(y.size() / 2));
  const Eigen::Vector2d c = x.rowwise().mean();
  const Eigen::VectorXd r = (x.colwise() - c).colwise().norm();
  return r.maxCoeff() - r.minCoeff();
}

} // namespace

TEST(CapsuleModel2DBending, DeckBuildsBendingOnlyWhenAskedAndRejectsANegativeModulus)
{
  const std::vector<std::string> base{"Cell/Number of points=32", "Wall/Enabled=false", "Cell/Lowest point height=-1"};
  const CapsuleModel2D plain = bendingModelOf(bendingDeck(base));
  auto withBending = base;
  withBending.emplace_back("Cell/Bending modulus=0.01");
  const CapsuleModel2D bent = bendingModelOf(bendingDeck(withBending));
  const contour::Contour initial = plain.contour(plain.initialState());
  EXPECT_EQ(plain.membrane(initial).bending(), nullptr);
  ASSERT_NE(bent.membrane(initial).bending(), nullptr);
  const auto mentions = [](const std::vector<std::string>& terms) {
    return std::any_of(terms.begin(), terms.end(), [](const std::string& t) { return t.find("bending") != t.npos; });
  };
  EXPECT_FALSE(mentions(plain.terms()));
  EXPECT_TRUE(mentions(bent.terms()));
  try {
    bendingDeck({"Cell/Bending modulus=-0.01"});
    FAIL() << "a negative bending modulus was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("Bending modulus"), std::string::npos) << e.what();
  }
}

TEST(CapsuleModel2DBending, CircleStaysAtRestAndAPerturbedCircleRelaxesTowardsOne)
{
  // Unbounded fluid at rest, Ca = 1, k_b = 0.1, 32 points. A circle whose membrane is unstressed
  // carries the uniform bending load -k_b / (2 R^3) n, whose single layer vanishes on a closed
  // contour (a uniform pressure moves no fluid): the circle stays at rest, but for what the
  // spline's curvature varies between the nodes (O(h^2), Bending2DLoad). Against the circle
  // prestressed by alpha = 0.1 without bending (uniform tension alpha E, load gamma kappa n), whose
  // drift has the same cause: the bending's q kappa^2 / 2 varies twice as much as gamma kappa
  // (measured drifts 4.6e-4 and 2.3e-4 of c max |Delta f|).
  const std::vector<std::string> circle32{"Cell/Number of points=32", "Wall/Enabled=false",
                                          "Cell/Lowest point height=-1", "Flow/Capillary number=1"};
  auto bendingSettings = circle32;
  bendingSettings.emplace_back("Cell/Bending modulus=0.1");
  auto tensionSettings = circle32;
  tensionSettings.emplace_back("Cell/Prestress=0.1");
  const auto relativeDrift = [](CapsuleModel2D& m) {
    RelaxationWithoutFlow u(m);
    const std::vector<double> x = m.initialState();
    const Eigen::Matrix2Xd load = m.membrane(m.contour(x)).load();
    const double c = 1.0 / (4.0 * M_PI * m.flow().conditions.capillaryNumber); // 1 / (2 pi (1 + lambda) Ca)
    return largest(u(x)) / (c * load.colwise().norm().maxCoeff());
  };
  CapsuleModel2D tensed = bendingModelOf(bendingDeck(tensionSettings));
  CapsuleModel2D model = bendingModelOf(bendingDeck(bendingSettings));
  const double bendingDrift = relativeDrift(model), tensionDrift = relativeDrift(tensed);
  std::printf("  circle at rest: max |u| / (c max |Delta f|) = %.3e with bending, %.3e with uniform tension\n",
              bendingDrift, tensionDrift);
  // Within 10% of twice the tension's; a q'' that is not zero on the circle, or a kappa taken
  // from another spline, would be a grid-scale load of O(h^2) = 4e-2 relative, 100 times more.
  EXPECT_LT(bendingDrift, 2.2 * tensionDrift);
  EXPECT_LT(bendingDrift, 1e-3);
  RelaxationWithoutFlow velocity(model);
  const std::vector<double> circle = model.initialState();

  // A circle perturbed by 0.05 cos 3 theta whose tension is unstressed in that shape
  // (regridFree makes it the reference): only the bending drives it, towards the circle, while
  // the tension resists. The Stokes flow dissipates, so the total energy falls at every step,
  // and the radial spread shrinks. RK4 with dt = 0.01 (the fastest rate, k_b (N/2)^3 / (4 Ca)
  // ~ 100, gives dt rho ~ 1, inside RK4's stability region), to k t = 3.
  std::vector<double> y(circle.size());
  Eigen::Matrix2Xd perturbed(2, model.numberOfNodes());
  for (int i = 0; i < model.numberOfNodes(); ++i) {
    const double theta = 2.0 * M_PI * i / model.numberOfNodes() - M_PI / 2.0;
    const double r = 1.0 + 0.05 * std::cos(3.0 * theta);
    perturbed.col(i) = Eigen::Vector2d(r * std::cos(theta), r * std::sin(theta));
  }
  model.regridFree(perturbed);
  std::copy(perturbed.data(), perturbed.data() + perturbed.size(), y.begin());
  const auto energy = [&](const std::vector<double>& state) {
    const scene2d::MembraneState2D m = model.membrane(model.contour(state));
    return std::pair<double, double>(m.elasticEnergy() + m.bendingEnergy(), m.bendingEnergy());
  };
  const double spread0 = radialSpread(y);
  auto [total, bending] = energy(y);
  const double dt = 0.01;
  bool falling = true;
  for (int step = 0; step < 300; ++step) {
    const auto k1 = velocity(y);
    std::vector<double> s(y.size());
    const auto stage = [&](const std::vector<double>& k, double f) {
      for (std::size_t i = 0; i < y.size(); ++i) {
        s[i] = y[i] + f * dt * k[i];
      }
      return velocity(s);
    };
    const auto k2 = stage(k1, 0.5);
    const auto k3 = stage(k2, 0.5);
    const auto k4 = stage(k3, 1.0);
    for (std::size_t i = 0; i < y.size(); ++i) {
      y[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    const auto [nextTotal, nextBending] = energy(y);
    falling = falling && nextTotal < total;
    total = nextTotal;
    bending = nextBending;
  }
  const double spread = radialSpread(y);
  std::printf("  perturbed circle: radial spread %.4f -> %.4f, energy %.4e (bending %.4e)\n", spread0, spread, total,
              bending);
  EXPECT_TRUE(falling);
  // Measured 0.1 -> 0.017 by k t = 3; half is far from both and from a wrong sign, which would
  // grow the mode.
  EXPECT_LT(spread, 0.5 * spread0);
}

// With 'Bending reference = Initial shape' the unstressed initial cell carries no load at all,
// so J~ (which differentiates the load function, bending included) is the derivative of the
// velocity there, as in VelocityJacobian2D.IsTheDerivativeOfTheVelocityAtRest and to its
// tolerance (1e-8 of |J~ v|: the central differences' truncation and round-off at e = 1e-6).
// The bending load is the stiffer part at this size (k_b (N/2)^3 ~ 40 against E N/2 ~ 16), so
// a bending load left out of J~ is an O(1) error.
TEST(CapsuleModel2DBending, JacobianIsTheDerivativeOfTheVelocityAtABendingFreeRest)
{
  for (const bool wall : {false, true}) {
    const auto deck =
        bendingDeck({"Cell/Number of points=32", "Cell/Aspect ratio=0.7", "Flow/Capillary number=0.05",
                     "Solver/Stiff/Gauss-Legendre points=0", "Cell/Bending modulus=0.01",
                     "Cell/Bending reference=Initial shape", wall ? "Wall/Enabled=true" : "Wall/Enabled=false",
                     wall ? "Cell/Lowest point height=0.1" : "Cell/Lowest point height=-1", "Tether/Enabled=false"});
    CapsuleModel2D model = bendingModelOf(deck);
    VelocityJacobian2D jacobian(model, bendingComm(), deck);
    const std::vector<double> x = model.initialState();
    jacobian.linearise(0.0, x);
    std::vector<double> v(x.size()), Jv(x.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      v[i] = std::sin(0.9 * static_cast<double>(i) + 0.4) + 0.5 * std::cos(0.07 * static_cast<double>(i));
    }
    jacobian.apply(v.data(), Jv.data());
    const double e = 1e-6;
    std::vector<double> plus(x), minus(x), up, um;
    for (std::size_t i = 0; i < x.size(); ++i) {
      plus[i] += e * v[i];
      minus[i] -= e * v[i];
    }
    model.rightHandSide(0.0, plus, up);
    model.rightHandSide(0.0, minus, um);
    double worst = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      worst = std::max(worst, std::abs(Jv[i] - (up[i] - um[i]) / (2 * e)));
    }
    EXPECT_LT(worst, 1e-8 * largest(Jv)) << (wall ? "wall" : "free space");
  }
}

// ROS34PW2 with fixed steps on a stiff 32-point cell with bending (Ca = 0.01, k_b = 0.01 flat,
// near the wall; the bending's fastest rate k_b (N/2)^3 / (4 Ca) ~ 1000 against steps of
// 0.025-0.0125, h rho ~ 10-25): the error at k t = 0.2 against a run with a quarter of the
// smallest step falls at order 3 (within 0.3), as without bending
// (VelocityJacobian2D.StiffCellRunConvergesAtOrderThree).
TEST(CapsuleModel2DBending, StiffRunWithBendingConvergesAtOrderThree)
{
  const auto deck = bendingDeck({"Cell/Number of points=32", "Flow/Capillary number=0.01", "Cell/Prestress=0.1",
                                 "Cell/Lowest point height=0.1", "Cell/Bending modulus=0.01",
                                 "Time integration/Method=ROS34PW2", "Time integration/Tolerance=1e-9"});
  const auto run = [&](int steps) {
    CapsuleModel2D model = bendingModelOf(deck);
    auto settings = timeint::timeIntegrationSettings(deck.sublist("Time integration"));
    settings.adaptive = false;
    settings.initialStep = 0.2 / steps;
    timeint::TimeIntegrator integrator(settings, [&model](double, const std::vector<double>& y,
                                                          std::vector<double>& u) { model.rightHandSide(0.0, y, u); });
    integrator.setLinearisedSystem(std::make_shared<VelocityJacobian2D>(model, bendingComm(), deck));
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
  const double order = capsula::testing::fittedOrder(counts, errors);
  std::printf("  ROS34PW2 with bending: errors %.3e %.3e %.3e, order %.2f\n", errors[0], errors[1], errors[2], order);
  EXPECT_NEAR(order, 3.0, 0.3);
}
