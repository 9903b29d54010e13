// Log-weighted Gauss rules, int_0^1 -ln(x) f(x) dx: exactness against the closed forms
// int_0^1 -ln(x) x^k dx = 1/(k+1)^2, and convergence for smooth non-polynomial f.
#include "capsula/testing/Constants.hpp"
#include "capsula/testing/ConvergenceOrder.hpp"

#include <capsula/quadrature/LogWeightedGauss.hpp>

#include <capsula/core/Error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

using capsula::testing::pi;

namespace {

using capsula::quadrature::logWeightedGauss;
using capsula::quadrature::Rule1D;

double apply(const Rule1D& rule, const std::function<double(double)>& f)
{
  double sum = 0.0;
  for (std::size_t k = 0; k < rule.points.size(); ++k) {
    sum += rule.weights[k] * f(rule.points[k]);
  }
  return sum;
}

// int_0^1 -ln(x) cos(x) dx = Si(1) (integrate by parts), Si(1) = sum_k (-1)^k / ((2k+1)(2k+1)!).
double sineIntegralOfOne()
{
  double sum = 0.0, factorial = 1.0; // (2k+1)!
  for (int k = 0; k < 12; ++k) {
    if (k > 0) {
      factorial *= (2.0 * k) * (2.0 * k + 1.0);
    }
    sum += ((k % 2 == 0) ? 1.0 : -1.0) / ((2.0 * k + 1.0) * factorial);
  }
  return sum;
}

// int_0^1 -ln(x) e^x dx = sum_k 1 / (k! (k+1)^2) (term-wise with the monomial moments).
double logMomentOfExp()
{
  double sum = 0.0, factorial = 1.0;
  for (int k = 0; k < 25; ++k) {
    if (k > 0) {
      factorial *= k;
    }
    sum += 1.0 / (factorial * (k + 1.0) * (k + 1.0));
  }
  return sum;
}

TEST(LogWeightedGauss, ExactToDegree2nMinus1)
{
  for (int n = 1; n <= 30; ++n) {
    const Rule1D rule = logWeightedGauss(n);
    ASSERT_EQ(rule.points.size(), static_cast<std::size_t>(n));
    for (int power = 0; power <= 2 * n - 1; ++power) {
      const double exact = 1.0 / ((power + 1.0) * (power + 1.0));
      const double value = apply(rule, [power](double x) { return std::pow(x, power); });
      // Positive weights and nodes, correctly rounded to ~1 ulp: no cancellation, but x^p
      // multiplies a node's rounding by p. Several ulps times p + 1 (<= 6e-14 here).
      EXPECT_NEAR(value, exact, 1e-15 * (power + 1) * exact) << "n = " << n << ", x^" << power;
    }
  }
}

TEST(LogWeightedGauss, NotExactAtDegree2n)
{
  // The error at x^{2n} is int -ln(x) pi_n(x)^2 dx > 0 (pi_n the monic orthogonal
  // polynomial): the rule underestimates, by far more than round-off for these n.
  for (int n = 1; n <= 8; ++n) {
    const Rule1D rule = logWeightedGauss(n);
    const double exact = 1.0 / ((2.0 * n + 1.0) * (2.0 * n + 1.0));
    const double value = apply(rule, [n](double x) { return std::pow(x, 2 * n); });
    EXPECT_GT(exact - value, 1e-8 * exact) << "n = " << n;
  }
}

TEST(LogWeightedGauss, OnePointRuleIsTheWeightsCentroid)
{
  // int -ln x = 1 and int -ln(x) x = 1/4: node 1/4, weight 1.
  const Rule1D rule = logWeightedGauss(1);
  EXPECT_NEAR(rule.points[0], 0.25, 1e-16);
  EXPECT_NEAR(rule.weights[0], 1.0, 1e-16);
}

TEST(LogWeightedGauss, TwoPointRuleToTheLastBit)
{
  // pi_2 = x^2 - (5/7) x + 17/252 from the moments 1, 1/4, 1/9, 1/16, so the nodes are
  // 5/14 -+ sqrt(106)/42 and the weights follow from w1 + w2 = 1, w1 x1 + w2 x2 = 1/4.
  const double x1 = 5.0 / 14.0 - std::sqrt(106.0) / 42.0;
  const double x2 = 5.0 / 14.0 + std::sqrt(106.0) / 42.0;
  const double w1 = (x2 - 0.25) / (x2 - x1);
  const double w2 = (0.25 - x1) / (x2 - x1);
  const Rule1D rule = logWeightedGauss(2);
  // Two ulps: the rule is computed in extended precision and rounded once; the closed
  // forms above round a few times in double.
  const double ulp = 2.3e-16;
  EXPECT_NEAR(rule.points[0], x1, 2 * ulp * x1);
  EXPECT_NEAR(rule.points[1], x2, 2 * ulp * x2);
  EXPECT_NEAR(rule.weights[0], w1, 2 * ulp * w1);
  EXPECT_NEAR(rule.weights[1], w2, 2 * ulp * w2);
}

TEST(LogWeightedGauss, NodesInsideAscendingWeightsPositiveSumToOne)
{
  for (int n : {2, 7, 20, 50, 100}) {
    const Rule1D rule = logWeightedGauss(n);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
      EXPECT_GT(rule.points[k], 0.0);
      EXPECT_LT(rule.points[k], 1.0);
      EXPECT_GT(rule.weights[k], 0.0);
      if (k > 0) {
        EXPECT_LT(rule.points[k - 1], rule.points[k]);
      }
      sum += rule.weights[k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-13) << "n = " << n; // int_0^1 -ln x dx = 1; ~n ulps
  }
}

TEST(LogWeightedGauss, ConvergesToSineIntegralForCosine)
{
  const double exact = sineIntegralOfOne();
  EXPECT_NEAR(exact, 0.946083070367183, 1e-15); // Si(1), Abramowitz & Stegun Table 5.1
  std::vector<double> errors;
  for (int n = 1; n <= 7; ++n) {
    errors.push_back(std::abs(apply(logWeightedGauss(n), [](double x) { return std::cos(x); }) - exact));
  }
  // The error of an entire function falls faster than geometrically, ~ 1/(4^{2n} (2n)!):
  // each step gains at least two digits until round-off (1e-16) is reached at n = 6.
  for (int n = 2; n <= 5; ++n) {
    EXPECT_LT(errors[n - 1], 1e-2 * errors[n - 2]) << "n = " << n;
  }
  EXPECT_LT(errors[5], 1e-15);
  EXPECT_LT(errors[6], 1e-15);
}

TEST(LogWeightedGauss, ConvergesForExponential)
{
  const double exact = logMomentOfExp();
  for (int n = 6; n <= 20; ++n) {
    const double value = apply(logWeightedGauss(n), [](double x) { return std::exp(x); });
    EXPECT_NEAR(value, exact, 1e-15 * exact) << "n = " << n; // converged to round-off
  }
}

TEST(LogWeightedGauss, GeometricRateForAPoleAtMinusOne)
{
  // int_0^1 -ln(x) / (1 + x) dx = pi^2 / 12. The pole of f at x = -1 is at t = -3 on
  // [-1, 1], so Gauss errors fall like rho^{-2n} with rho = 3 + sqrt(8): fit the slope of
  // ln(error) against n and compare with -2 ln(rho) (within 10%: the algebraic prefactor
  // bends the line slightly over n = 2..8).
  const double exact = pi * pi / 12.0;
  std::vector<double> points, logErrors;
  for (int n = 2; n <= 8; ++n) {
    const double value = apply(logWeightedGauss(n), [](double x) { return 1.0 / (1.0 + x); });
    points.push_back(n);
    logErrors.push_back(std::log(std::abs(value - exact)));
  }
  const double slope = capsula::testing::leastSquaresSlope(points, logErrors);
  const double expected = -2.0 * std::log(3.0 + std::sqrt(8.0));
  EXPECT_NEAR(slope, expected, 0.1 * std::abs(expected)) << "fitted slope " << slope;
  const double value20 = apply(logWeightedGauss(20), [](double x) { return 1.0 / (1.0 + x); });
  EXPECT_NEAR(value20, exact, 1e-15); // rho^{-40} ~ 1e-31: only round-off remains
}

TEST(LogWeightedGauss, RejectsBadOrder)
{
  for (int n : {0, -2, capsula::quadrature::maxLogWeightedGaussOrder + 1}) {
    try {
      logWeightedGauss(n);
      FAIL() << "n = " << n << " was accepted";
    } catch (const capsula::core::InputError& error) {
      EXPECT_NE(std::string(error.what()).find("n = " + std::to_string(n)), std::string::npos) << error.what();
    }
  }
}

} // namespace
