// Bond kinetics against the master equation: lifetimes under a fixed force (Bell and Dembo),
// the relaxation of the bound fraction under constant rates, the mean field's exactness, and
// the steady bound fraction of a clamped population at steps from 1e-3 to 1 times 1 / k_off.
#include <capsula/adhesion/BondKinetics.hpp>
#include <capsula/adhesion/BondPopulation.hpp>
#include <capsula/adhesion/Receptors.hpp>
#include <capsula/mesh/Icosphere.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace adhesion = capsula::adhesion;
namespace mesh = capsula::mesh;
using mesh::Vec3;

namespace {

// >= 10^4 receptors on a unit sphere centred 1.5 above the wall (density 1000 per a^2).
struct KineticsEnsemble {
  mesh::SurfaceMesh sphere = mesh::makeIcosphere(2);
  std::vector<double> x;
  adhesion::ReceptorSet receptors;
  KineticsEnsemble() : receptors(sphere, sphere.positions(), 1000.0, 2024, 0)
  {
    x = sphere.positions();
    for (std::size_t i = 1; i < x.size(); i += 3) {
      x[i] += 1.5;
    }
  }
};

struct LifetimeStatistics {
  double mean = 0.0;
  double standardError = 0.0;
  int samples = 0;
};

// Binds every receptor with a bond of length `length` (anchor straight below, the membrane
// held still, so the force stays fixed) and steps until all have broken. A bond that breaks
// in step n lived between (n - 1) dt and n dt: its lifetime is taken as (n - 1/2) dt, whose
// mean is 1/k (1 + (k dt)^2 / 12 + ...) for the geometric law of the steps.
LifetimeStatistics measureLifetimes(const adhesion::AdhesionSettings& s, double length, double dt)
{
  KineticsEnsemble e;
  adhesion::BondPopulation bonds(s, 0, e.receptors.size());
  for (int r = 0; r < e.receptors.size(); ++r) {
    bonds.setState(r, {1.0, e.receptors.position(e.sphere, e.x.data(), r) - Vec3(0.0, length, 0.0)});
  }
  std::vector<double> lifetimes;
  std::vector<bool> alive(static_cast<std::size_t>(e.receptors.size()), true);
  for (std::uint64_t step = 1; lifetimes.size() < alive.size() && step < 1000000; ++step) {
    bonds.update(e.sphere, e.receptors, e.x.data(), dt, step);
    for (int r = 0; r < e.receptors.size(); ++r) {
      if (alive[static_cast<std::size_t>(r)] && bonds.state(r).occupancy == 0.0) {
        alive[static_cast<std::size_t>(r)] = false;
        lifetimes.push_back((static_cast<double>(step) - 0.5) * dt);
      }
    }
  }
  LifetimeStatistics out;
  out.samples = static_cast<int>(lifetimes.size());
  double sum = 0.0, sumSquares = 0.0;
  for (const double t : lifetimes) {
    sum += t;
    sumSquares += t * t;
  }
  out.mean = sum / out.samples;
  out.standardError = std::sqrt((sumSquares / out.samples - out.mean * out.mean) / out.samples);
  return out;
}

// Receptors far above the reaction distance (no rebinding).
adhesion::AdhesionSettings lifetimeSettings(adhesion::BondModel model)
{
  adhesion::AdhesionSettings s;
  s.model = model;
  s.springConstant = 10.0;
  s.equilibriumLength = 0.02;
  s.thermalEnergy = 1e-4;
  s.reactiveCompliance = 1e-3;
  s.offRate = 1.0;
  s.reactionDistance = 0.01;
  return s;
}

} // namespace

TEST(BondKinetics, BellLifetimeIsTheInverseOffRate)
{
  const auto s = lifetimeSettings(adhesion::BondModel::Slip);
  const double length = 0.03; // |F| = 10 x 0.01 = 0.1: gamma |F| / kT = 1e-3 x 0.1 / 1e-4 = 1
  const double k = 1.0 * std::exp(1.0);
  EXPECT_NEAR(adhesion::offRate(s, length), k, 1e-14 * k);
  const auto t = measureLifetimes(s, length, 0.005); // k dt = 0.014: bias (k dt)^2/12 = 1.6e-5
  ASSERT_GE(t.samples, 10000);
  // 4 standard errors (~4% at N ~ 12,600): a factor e of a missing force term is 60 SE off.
  EXPECT_NEAR(t.mean, 1.0 / k, 4.0 * t.standardError) << "SE " << t.standardError;
  std::printf("Bell: N = %d, mean lifetime %.5f, 1/k_off %.5f, SE %.5f\n", t.samples, t.mean, 1.0 / k, t.standardError);
}

TEST(BondKinetics, DemboLifetimeIsTheInverseOffRateForSlipAndCatch)
{
  auto s = lifetimeSettings(adhesion::BondModel::CatchSlip);
  const double length = 0.03; // y = 0.01: y^2 / (2 kT) = 0.5 per unit of sigma - sigma_ts
  for (const double transition : {5.0, 15.0}) {
    s.transitionSpringConstant = transition;
    const double k = std::exp((10.0 - transition) * 0.5); // slip: e^2.5; catch: e^-2.5
    EXPECT_NEAR(adhesion::offRate(s, length), k, 1e-13 * k);
    const double dt = 0.01 / k; // k dt = 0.01
    const auto t = measureLifetimes(s, length, dt);
    ASSERT_GE(t.samples, 10000);
    EXPECT_NEAR(t.mean, 1.0 / k, 4.0 * t.standardError) << "sigma_ts " << transition; // as for Bell
    std::printf("Dembo sigma_ts = %g: N = %d, mean lifetime %.5f, 1/k_off %.5f, SE %.5f\n", transition, t.samples,
                t.mean, 1.0 / k, t.standardError);
  }
}

TEST(BondKinetics, BoundFractionRelaxesAtTheSumOfTheRates)
{
  // Rates independent of the stretch (sigma ~ 0) and every receptor within reach: a
  // two-state Markov chain, p(t) = p_eq (1 - exp(-(k_on + k_off) t)).
  adhesion::AdhesionSettings s;
  s.springConstant = 1e-12;
  s.reactiveCompliance = 0.0;
  s.thermalEnergy = 1.0;
  s.reactionDistance = 3.0;
  s.onRate = 0.02;
  s.ligandDensity = 100.0; // k_on = 2
  s.offRate = 1.0;
  const double kOn = 2.0, kOff = 1.0, rate = kOn + kOff, equilibrium = kOn / rate;
  const double dt = 1.0 / 1500.0;
  for (const auto kinetics : {adhesion::BondKinetics::Stochastic, adhesion::BondKinetics::MeanField}) {
    s.kinetics = kinetics;
    KineticsEnsemble e;
    adhesion::BondPopulation bonds(s, 0, e.receptors.size());
    const int n = e.receptors.size();
    ASSERT_GE(n, 10000);
    for (std::uint64_t step = 1; step <= 1500; ++step) {
      bonds.update(e.sphere, e.receptors, e.x.data(), dt, step);
      if (step % 250 != 0) {
        continue;
      }
      const double t = static_cast<double>(step) * dt;
      const double expected = equilibrium * (1.0 - std::exp(-rate * t));
      const double fraction = bonds.bondCount() / n;
      if (kinetics == adhesion::BondKinetics::MeanField) {
        // Exact solution over each step; the rates differ from constants by sigma y^2/(2kT)
        // < 1e-11: the only error is round-off accumulated over 1500 steps.
        EXPECT_NEAR(fraction, expected, 1e-10) << "t = " << t;
        EXPECT_NEAR(bonds.state(n / 2).occupancy, expected, 1e-10);
        continue;
      }
      // Binomial standard error; the step's bias (O(k dt) ~ 2e-3 relative in the rate, 1e-4
      // in p_eq) is far below it.
      const double se = std::sqrt(expected * (1.0 - expected) / n);
      EXPECT_NEAR(fraction, expected, 4.0 * se) << "t = " << t;
      if (step == 500) {
        // The rate itself, from p(1/3): -ln(1 - p/p_eq) / t, its SE propagated from p's.
        const double measured = -std::log(1.0 - fraction / equilibrium) / t;
        const double rateSe = se / ((equilibrium - expected) * t);
        EXPECT_NEAR(measured, rate, 4.0 * rateSe);
        std::printf("bound fraction at t = 1/3: %.4f (expected %.4f, SE %.4f); rate %.3f (expected 3, SE %.3f)\n",
                    fraction, expected, se, measured, rateSe);
      }
    }
  }
}

TEST(BondKinetics, MeanFieldSurvivalIsTheExponentialOfTheOffRate)
{
  for (const auto model : {adhesion::BondModel::Slip, adhesion::BondModel::CatchSlip}) {
    auto s = lifetimeSettings(model);
    s.kinetics = adhesion::BondKinetics::MeanField;
    s.transitionSpringConstant = 5.0;
    KineticsEnsemble e;
    adhesion::BondPopulation bonds(s, 0, e.receptors.size());
    const Vec3 x = e.receptors.position(e.sphere, e.x.data(), 0);
    bonds.setState(0, {1.0, x - Vec3(0.0, 0.03, 0.0)});
    const double k = adhesion::offRate(s, 0.03), dt = 0.01;
    for (std::uint64_t step = 1; step <= 50; ++step) {
      bonds.update(e.sphere, e.receptors, e.x.data(), dt, step, 0, 1);
    }
    // exp(-k dt) applied 50 times: exact up to 50 roundings.
    EXPECT_NEAR(bonds.state(0).occupancy, std::exp(-k * 50 * dt), 1e-13);
  }
}

namespace {

// The KineticsEnsemble flattened onto the plane y = height: every receptor at that height,
// all with the same rates, held still (a clamped population).
struct ClampedEnsemble : KineticsEnsemble {
  explicit ClampedEnsemble(double height)
  {
    for (std::size_t i = 1; i < x.size(); i += 3) {
      x[i] = height;
    }
  }
};

struct SteadyFraction {
  double mean = 0.0;
  double standardError = 0.0;
};

// The bound fraction of a clamped stochastic population started at the exact steady fraction
// `exact`, stepped with dt for 3 relaxation times 1 / (k_on + k_off) and then averaged over
// every step of `window` relaxation times (at least 16 steps). Its standard error, of the
// two-state chain: the steps' fractions have variance p (1 - p) / N and correlation
// rho = exp(-(k_on + k_off) dt) from one step to the next, so the mean of M steps has variance
// p (1 - p) / (N M) (1 + rho) / (1 - rho) (to O(1/M)).
SteadyFraction stochasticSteadyFraction(const adhesion::AdhesionSettings& s, const ClampedEnsemble& e, double rate,
                                        double exact, double dt, double window)
{
  adhesion::BondPopulation bonds(s, 0, e.receptors.size());
  const int n = e.receptors.size();
  for (int r = 0; r < static_cast<int>(std::lround(exact * n)); ++r) {
    const Vec3 p = e.receptors.position(e.sphere, e.x.data(), r);
    bonds.setState(r, {1.0, Vec3(p[0], 0.0, p[2])});
  }
  const auto burnIn = static_cast<std::uint64_t>(std::ceil(3.0 / (rate * dt)));
  const auto averaged = std::max<std::uint64_t>(16, static_cast<std::uint64_t>(std::ceil(window / (rate * dt))));
  double sum = 0.0;
  for (std::uint64_t step = 1; step <= burnIn + averaged; ++step) {
    bonds.update(e.sphere, e.receptors, e.x.data(), dt, step);
    if (step > burnIn) {
      sum += bonds.bondCount() / n;
    }
  }
  const double rho = std::exp(-rate * dt), m = static_cast<double>(averaged);
  return {sum / m, std::sqrt(exact * (1.0 - exact) / (n * m) * (1.0 + rho) / (1.0 - rho))};
}

// Steps the mean-field occupancy of one clamped receptor from 0 for 40 relaxation times
// (exp(-40) ~ 4e-18 of the start left) and returns it.
double meanFieldSteadyFraction(adhesion::AdhesionSettings s, const ClampedEnsemble& e, double rate, double dt)
{
  s.kinetics = adhesion::BondKinetics::MeanField;
  adhesion::BondPopulation bonds(s, 0, e.receptors.size());
  const auto steps = static_cast<std::uint64_t>(std::ceil(40.0 / (rate * dt)));
  for (std::uint64_t step = 1; step <= steps; ++step) {
    bonds.update(e.sphere, e.receptors, e.x.data(), dt, step, 0, 1);
  }
  return bonds.state(0).occupancy;
}

// The steady fraction of a clamped population at steps dt = c / k_off, c = 1e-3 .. 1: the
// mean field from 0 to round-off, the stochastic one (>= 12,000 receptors averaged over 20
// relaxation times) to 1%.
void expectSteadyFractionAtEveryStep(const adhesion::AdhesionSettings& s, double height)
{
  const ClampedEnsemble e(height);
  ASSERT_GE(e.receptors.size(), 10000);
  const Vec3 x0 = e.receptors.position(e.sphere, e.x.data(), 0);
  const double kOn = adhesion::onRate(s, height, x0[0], x0[2]), kOff = adhesion::offRate(s, height);
  const double rate = kOn + kOff, exact = kOn / rate;
  for (const double c : {1e-3, 1e-2, 1e-1, 1.0}) {
    const double dt = c / kOff;
    // The mean field solves the master equation exactly over each step: round-off only.
    EXPECT_NEAR(meanFieldSteadyFraction(s, e, rate, dt), exact, 1e-12) << "k_off dt = " << c;
    // 20 relaxation times hold a standard error of 0.2% of p for p ~ 2/3: 1% is 5 SE.
    const SteadyFraction f = stochasticSteadyFraction(s, e, rate, exact, dt, 20.0);
    ASSERT_LT(4.0 * f.standardError, 0.01 * exact) << "the window is too short to test 1%";
    EXPECT_NEAR(f.mean, exact, 0.01 * exact) << "k_off dt = " << c;
    std::printf("k_off dt = %-6g stochastic %.5f (SE %.5f), exact %.5f, one event per step would give %.5f\n", c,
                f.mean, f.standardError, exact,
                adhesion::eventProbability(kOn, dt) /
                    (adhesion::eventProbability(kOn, dt) + adhesion::eventProbability(kOff, dt)));
  }
}

} // namespace

// One event per receptor per step settles at p_on / (p_on + p_off): 0.578 at k_on = 2, k_off =
// 1, dt = 1 against 2/3. The exact two-state chain over the step settles at 2/3 at every step.
TEST(BondKinetics, SteadyFractionDoesNotDependOnTheStep)
{
  adhesion::AdhesionSettings s; // rates independent of the stretch (sigma ~ 0), as above
  s.springConstant = 1e-12;
  s.reactiveCompliance = 0.0;
  s.thermalEnergy = 1.0;
  s.reactionDistance = 0.05;
  s.onRate = 0.02;
  s.ligandDensity = 100.0; // k_on = 2
  s.offRate = 1.0;
  expectSteadyFractionAtEveryStep(s, 0.03);
}

// Bell loading: bonds stretched by y = 0.01 (|F| = 0.1, gamma |F| / kT = 1: k_off = e), the
// on-rate from detailed balance (k_on = k_on0 n_L exp(sigma y (gamma - y/2) / kT) = 300
// e^-4 = 5.49): the same at every step, the force being fixed while the cell is held still.
TEST(BondKinetics, BellSteadyFractionDoesNotDependOnTheStep)
{
  adhesion::AdhesionSettings s;
  s.springConstant = 10.0;
  s.equilibriumLength = 0.02;
  s.reactiveCompliance = 1e-3;
  s.thermalEnergy = 1e-4;
  s.reactionDistance = 0.05;
  s.onRate = 3.0;
  s.ligandDensity = 100.0;
  s.offRate = 1.0;
  EXPECT_NEAR(adhesion::offRate(s, 0.03), std::exp(1.0), 1e-14 * std::exp(1.0));
  EXPECT_NEAR(adhesion::onRate(s, 0.03, 0.0, 0.0), 300.0 * std::exp(-4.0), 1e-12);
  expectSteadyFractionAtEveryStep(s, 0.03);
}

// The ligand wall: bonds to a channel's upper wall y = H are the mirror images of bonds to the
// lower wall. The ensemble's positions reflected y -> H - y put every receptor at the same gap
// from the upper wall as from the lower wall before; the draws are keyed by (seed, stream,
// receptor, step), so both populations see the same events: equal occupancies, anchors on
// y = H at the mirrored points, forces with the normal component reversed, at every step of
// both kinetics. Measured 1.2e-14 (stochastic) and 2.1e-13 (mean field, whose occupancies
// pass through exponentials of the gaps); bound 1e-12. A population still tied to the
// lower wall binds nothing near the upper wall (every receptor beyond the reach of y = 0).
TEST(BondKinetics, BondsToTheUpperWallAreTheMirrorOfBondsToTheLowerWall)
{
  const double H = 4.0;
  for (const adhesion::BondKinetics kinetics :
       {adhesion::BondKinetics::Stochastic, adhesion::BondKinetics::MeanField}) {
    KineticsEnsemble e;
    for (std::size_t i = 1; i < e.x.size(); i += 3) {
      e.x[i] -= 1.5 - 1.01; // the sphere 0.01 above the lower wall: its cap within the reach
    }
    std::vector<double> mirrored = e.x;
    for (std::size_t i = 1; i < mirrored.size(); i += 3) {
      mirrored[i] = H - mirrored[i];
    }
    adhesion::AdhesionSettings lower;
    lower.kinetics = kinetics;
    lower.reactionDistance = 0.05;
    lower.onRate = 1.0;
    adhesion::AdhesionSettings upper = lower;
    upper.ligandWall = adhesion::ligandWallPlane(adhesion::LigandWallChoice::Upper, H);
    adhesion::BondPopulation below(lower, 0, e.receptors.size()), above(upper, 0, e.receptors.size());
    adhesion::BondPopulation wrongWall(lower, 0, e.receptors.size());
    double largestDifference = 0.0;
    for (std::uint64_t step = 1; step <= 20; ++step) {
      below.update(e.sphere, e.receptors, e.x.data(), 0.05, step);
      above.update(e.sphere, e.receptors, mirrored.data(), 0.05, step);
      wrongWall.update(e.sphere, e.receptors, mirrored.data(), 0.05, step);
      for (int r = 0; r < e.receptors.size(); ++r) {
        const adhesion::BondState& a = below.state(r);
        const adhesion::BondState& b = above.state(r);
        const Vec3 fa = below.force(r, e.receptors.position(e.sphere, e.x.data(), r));
        const Vec3 fb = above.force(r, e.receptors.position(e.sphere, mirrored.data(), r));
        largestDifference = std::max({largestDifference, std::abs(a.occupancy - b.occupancy), std::abs(fa[0] - fb[0]),
                                      std::abs(fa[1] + fb[1]), std::abs(fa[2] - fb[2])});
        if (a.occupancy > 0.0) { // a free receptor's anchor means nothing
          largestDifference =
              std::max({largestDifference, std::abs(a.anchor[0] - b.anchor[0]),
                        std::abs(a.anchor[1] - (H - b.anchor[1])), std::abs(a.anchor[2] - b.anchor[2])});
        }
      }
    }
    std::printf("%s: %.0f bonds to the lower wall, %.0f to the upper, largest difference %.2e, %.0f to the wrong "
                "wall\n",
                adhesion::to_string(kinetics).c_str(), below.bondCount(), above.bondCount(), largestDifference,
                wrongWall.bondCount());
    EXPECT_GT(below.bondCount(), 10.0); // the cap within the reach binds
    EXPECT_LT(largestDifference, 1e-12);
    EXPECT_EQ(wrongWall.bondCount(), 0.0);
  }
}

TEST(BondKinetics, UpperLigandWallNeedsAChannel)
{
  try {
    adhesion::ligandWallPlane(adhesion::LigandWallChoice::Upper, 0.0);
    FAIL() << "an upper ligand wall without a channel was accepted";
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find("'Adhesion/Ligand wall' = Upper"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("'Wall/Channel height'"), std::string::npos) << error.what();
  }
  const adhesion::WallPlane lowerWall = adhesion::ligandWallPlane(adhesion::LigandWallChoice::Lower, 0.0);
  EXPECT_EQ(lowerWall.height, 0.0);
  EXPECT_EQ(lowerWall.fluidSide, 1);
}

// In a periodic box a bounded ligand patch repeats with the box: a point one period away along
// x or z (or several) is on the patch exactly when its image in the box is.
TEST(WallRectangle, APatchInAPeriodicBoxRepeatsWithTheBox)
{
  adhesion::WallRectangle patch{1.0, 2.0, 0.5, 1.5};
  EXPECT_TRUE(patch.contains(1.5, 1.0));
  EXPECT_FALSE(patch.contains(1.5 + 6.0, 1.0)); // no period: only the patch itself
  patch.periodX = 6.0;
  patch.periodZ = 4.0;
  EXPECT_TRUE(patch.contains(1.5 + 6.0, 1.0));
  EXPECT_TRUE(patch.contains(1.5 - 12.0, 1.0 + 8.0));
  EXPECT_FALSE(patch.contains(2.5 + 6.0, 1.0));
  EXPECT_FALSE(patch.contains(1.5, 1.7 - 4.0));
}
