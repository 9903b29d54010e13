// Gauss-Legendre rules: exactness to degree 2n-1, the exact error at degree 2n, symmetry.
#include <capsula/quadrature/GaussLegendre.hpp>

#include <capsula/core/Error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using capsula::quadrature::gaussLegendre;
using capsula::quadrature::Rule1D;

double integrate(const Rule1D& rule, int power)
{
  double sum = 0.0;
  for (std::size_t k = 0; k < rule.points.size(); ++k) {
    sum += rule.weights[k] * std::pow(rule.points[k], power);
  }
  return sum;
}

TEST(GaussLegendre, ExactToDegree2nMinus1OnUnitInterval)
{
  for (int n = 1; n <= 30; ++n) {
    const Rule1D rule = gaussLegendre(n);
    ASSERT_EQ(rule.points.size(), static_cast<std::size_t>(n));
    for (int power = 0; power <= 2 * n - 1; ++power) {
      const double exact = 1.0 / (power + 1);
      // Positive weights and nodes: the sum has no cancellation, a few ulps per term.
      EXPECT_NEAR(integrate(rule, power), exact, 1e-14 * exact) << "n = " << n << ", x^" << power;
    }
  }
}

TEST(GaussLegendre, ExactOnGeneralInterval)
{
  const double a = -2.0, b = 3.0;
  for (int n = 1; n <= 30; ++n) {
    const Rule1D rule = gaussLegendre(n, a, b);
    for (int power = 0; power <= 2 * n - 1; ++power) {
      const double exact = (std::pow(b, power + 1) - std::pow(a, power + 1)) / (power + 1);
      // Odd powers cancel between the two sides: compare with the size of the terms,
      // int |x|^p = (b^{p+1} + |a|^{p+1}) / (p+1). x^p multiplies a node's rounding of the
      // affine map (~1 ulp) by p, hence a tolerance of several ulps times p + 1.
      const double scale = (std::pow(b, power + 1) + std::pow(-a, power + 1)) / (power + 1);
      EXPECT_NEAR(integrate(rule, power), exact, 1e-15 * (power + 1) * scale) << "n = " << n << ", x^" << power;
    }
  }
}

TEST(GaussLegendre, ErrorAtDegree2nIsTheClassicalRemainder)
{
  // On [-1, 1]: int f - sum w f = 2^{2n+1} (n!)^4 / ((2n+1) ((2n)!)^3) f^{(2n)}; for
  // f = x^{2n}, f^{(2n)} = (2n)!. Matching it shows the degree is exactly 2n - 1.
  for (int n = 1; n <= 10; ++n) {
    const Rule1D rule = gaussLegendre(n, -1.0, 1.0);
    const double exact = 2.0 / (2 * n + 1);
    const double nFactorial = std::tgamma(n + 1.0);
    const double twoNFactorial = std::tgamma(2.0 * n + 1.0);
    const double remainder =
        std::pow(2.0, 2 * n + 1) * std::pow(nFactorial, 4) / ((2 * n + 1) * twoNFactorial * twoNFactorial);
    // The remainder is >= 1e-6 of the integral here; 1e-9 relative leaves it 3 digits.
    EXPECT_NEAR(exact - integrate(rule, 2 * n), remainder, 1e-9 * remainder) << "n = " << n;
  }
}

TEST(GaussLegendre, KnownLowOrderRules)
{
  // Newton stops within an ulp or two of the root; the weight formula adds a few more.
  const double ulps = 1e-15;
  const Rule1D two = gaussLegendre(2, -1.0, 1.0);
  EXPECT_NEAR(two.points[0], -1.0 / std::sqrt(3.0), ulps);
  EXPECT_NEAR(two.points[1], 1.0 / std::sqrt(3.0), ulps);
  EXPECT_NEAR(two.weights[0], 1.0, ulps);
  const Rule1D three = gaussLegendre(3, -1.0, 1.0);
  EXPECT_NEAR(three.points[0], -std::sqrt(0.6), ulps);
  EXPECT_EQ(three.points[1], 0.0);
  EXPECT_NEAR(three.weights[0], 5.0 / 9.0, ulps);
  EXPECT_NEAR(three.weights[1], 8.0 / 9.0, ulps);
}

TEST(GaussLegendre, AscendingSymmetricAndPositive)
{
  for (int n : {1, 2, 5, 12, 31, 64}) {
    const Rule1D rule = gaussLegendre(n, 0.0, 1.0);
    for (int k = 0; k < n; ++k) {
      EXPECT_GT(rule.points[k], 0.0);
      EXPECT_LT(rule.points[k], 1.0);
      EXPECT_GT(rule.weights[k], 0.0);
      if (k > 0) {
        EXPECT_LT(rule.points[k - 1], rule.points[k]);
      }
      // Mirrored construction: symmetric to round-off of the affine map.
      EXPECT_NEAR(rule.points[k] + rule.points[n - 1 - k], 1.0, 4e-16);
      EXPECT_EQ(rule.weights[k], rule.weights[n - 1 - k]);
    }
  }
}

TEST(GaussLegendre, RejectsBadInput)
{
  try {
    gaussLegendre(0);
    FAIL() << "n = 0 was accepted";
  } catch (const capsula::core::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("n = 0"), std::string::npos) << error.what();
  }
  EXPECT_THROW(gaussLegendre(-3), capsula::core::InputError);
  EXPECT_THROW(gaussLegendre(4, 1.0, 1.0), capsula::core::InputError);
  EXPECT_THROW(gaussLegendre(4, 2.0, 1.0), capsula::core::InputError);
}

} // namespace
