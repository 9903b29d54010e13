// Gauss rules on the reference triangle: the monomial test (exact to the stated degree,
// not beyond), weights, symmetry, the collapsed rule, and rejection of unknown N_Q.
#include <capsula/quadrature/TriangleRule.hpp>

#include <capsula/core/Error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using capsula::quadrature::collapsedTriangleRule;
using capsula::quadrature::supportedTriangleRules;
using capsula::quadrature::triangleRule;
using capsula::quadrature::TriangleRule;

// int_T xi^a eta^b = a! b! / (a + b + 2)!
double exactMonomial(int a, int b)
{
  return std::tgamma(a + 1.0) * std::tgamma(b + 1.0) / std::tgamma(a + b + 3.0);
}

double ruleMonomial(const TriangleRule& rule, int a, int b)
{
  double sum = 0.0;
  for (int k = 0; k < rule.size(); ++k) {
    sum += rule.weight[k] * std::pow(rule.xi[k], a) * std::pow(rule.eta[k], b);
  }
  return sum;
}

double relativeError(const TriangleRule& rule, int a, int b)
{
  const double exact = exactMonomial(a, b);
  return std::abs(ruleMonomial(rule, a, b) - exact) / exact;
}

// Largest relative monomial error over total degree `degree` exactly.
double worstErrorAtDegree(const TriangleRule& rule, int degree)
{
  double worst = 0.0;
  for (int a = 0; a <= degree; ++a) {
    worst = std::max(worst, relativeError(rule, a, degree - a));
  }
  return worst;
}

TEST(TriangleRules, SupportsTheThesisCounts)
{
  const std::vector<int> counts = supportedTriangleRules();
  for (int required : {1, 3, 4, 6, 7, 9, 12, 13, 16, 19}) {
    EXPECT_NE(std::find(counts.begin(), counts.end(), required), counts.end()) << required;
  }
  EXPECT_TRUE(std::is_sorted(counts.begin(), counts.end()));
}

TEST(TriangleRules, StatedDegrees)
{
  const std::vector<std::pair<int, int>> countAndDegree = {{1, 1}, {3, 2},  {4, 3},  {6, 4},  {7, 5},
                                                           {9, 5}, {12, 6}, {13, 7}, {16, 8}, {19, 9}};
  for (const auto& [count, degree] : countAndDegree) {
    EXPECT_EQ(triangleRule(count).degree, degree) << "N_Q = " << count;
    EXPECT_EQ(triangleRule(count).size(), count);
  }
}

TEST(TriangleRules, ExactForEveryMonomialUpToTheDegree)
{
  for (int count : supportedTriangleRules()) {
    const TriangleRule& rule = triangleRule(count);
    for (int degree = 0; degree <= rule.degree; ++degree) {
      // 20-digit tables: only the round-off of <= 19 terms remains, some of mixed sign
      // (4 and 13 points); observed <= 4.4e-16, so 2e-15 leaves a margin of 4.
      EXPECT_LT(worstErrorAtDegree(rule, degree), 2e-15) << "N_Q = " << count << ", degree " << degree;
    }
  }
}

TEST(TriangleRules, DegreeIsNotOverstated)
{
  for (int count : supportedTriangleRules()) {
    const TriangleRule& rule = triangleRule(count);
    // The smallest such error among these rules is 8.9e-4 (12 points): far above round-off.
    EXPECT_GT(worstErrorAtDegree(rule, rule.degree + 1), 1e-4) << "N_Q = " << count;
  }
}

TEST(TriangleRules, WeightsSumToAreaAndPointsLieInside)
{
  for (int count : supportedTriangleRules()) {
    const TriangleRule& rule = triangleRule(count);
    double sum = 0.0;
    for (int k = 0; k < rule.size(); ++k) {
      sum += rule.weight[k];
      EXPECT_GT(rule.xi[k], 0.0);
      EXPECT_GT(rule.eta[k], 0.0);
      EXPECT_LT(rule.xi[k] + rule.eta[k], 1.0);
    }
    EXPECT_NEAR(sum, 0.5, 1e-15) << "N_Q = " << count; // ~N_Q ulps
    const bool hasNegativeWeight =
        std::any_of(rule.weight.begin(), rule.weight.end(), [](double w) { return w < 0.0; });
    EXPECT_EQ(hasNegativeWeight, count == 4 || count == 13) << "N_Q = " << count;
  }
}

TEST(TriangleRules, InvariantUnderTheTriangleSymmetries)
{
  // Reflection (xi, eta) -> (eta, xi) and rotation (xi, eta) -> (eta, 1 - xi - eta) map
  // each rule onto itself (point with weight), so it cannot prefer a vertex.
  for (int count : supportedTriangleRules()) {
    const TriangleRule& rule = triangleRule(count);
    auto contains = [&rule](double xi, double eta, double weight) {
      for (int k = 0; k < rule.size(); ++k) {
        // The tables are built from the same barycentric numbers: equal to round-off.
        if (std::abs(rule.xi[k] - xi) < 1e-15 && std::abs(rule.eta[k] - eta) < 1e-15 && rule.weight[k] == weight) {
          return true;
        }
      }
      return false;
    };
    for (int k = 0; k < rule.size(); ++k) {
      EXPECT_TRUE(contains(rule.eta[k], rule.xi[k], rule.weight[k])) << "N_Q = " << count;
      EXPECT_TRUE(contains(rule.eta[k], 1.0 - rule.xi[k] - rule.eta[k], rule.weight[k])) << "N_Q = " << count;
    }
  }
}

TEST(TriangleRules, RejectsUnknownCountNamingItAndTheSupportedOnes)
{
  for (int count : {0, 2, 5, 8, -7, 1000}) {
    try {
      triangleRule(count);
      FAIL() << "N_Q = " << count << " was accepted";
    } catch (const capsula::core::InputError& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find("N_Q = " + std::to_string(count)), std::string::npos) << what;
      EXPECT_NE(what.find("1, 3, 4, 6, 7, 9, 12, 13, 16, 19"), std::string::npos) << what;
    }
  }
}

TEST(CollapsedTriangleRule, ExactToDegree2nMinus2AndNotBeyond)
{
  for (int n = 1; n <= 12; ++n) {
    const TriangleRule rule = collapsedTriangleRule(n);
    ASSERT_EQ(rule.size(), n * n);
    EXPECT_EQ(rule.degree, 2 * n - 2);
    for (int degree = 0; degree <= rule.degree; ++degree) {
      // Positive weights and points: round-off only.
      EXPECT_LT(worstErrorAtDegree(rule, degree), 1e-13) << "n = " << n << ", degree " << degree;
    }
    EXPECT_GT(worstErrorAtDegree(rule, rule.degree + 1), 1e-9) << "n = " << n;
  }
}

TEST(CollapsedTriangleRule, ConvergesForASmoothFunction)
{
  // int_T exp(xi + eta) = int_0^1 s e^s ds = 1 (s = xi + eta has density s on T).
  auto integrate = [](const TriangleRule& rule) {
    double sum = 0.0;
    for (int k = 0; k < rule.size(); ++k) {
      sum += rule.weight[k] * std::exp(rule.xi[k] + rule.eta[k]);
    }
    return sum;
  };
  double previous = std::abs(integrate(collapsedTriangleRule(1)) - 1.0);
  for (int n = 2; n <= 5; ++n) {
    const double error = std::abs(integrate(collapsedTriangleRule(n)) - 1.0);
    EXPECT_LT(error, 1e-2 * previous) << "n = " << n; // spectral: >= 2 digits per point
    previous = error;
  }
  EXPECT_NEAR(integrate(collapsedTriangleRule(8)), 1.0, 1e-15);
  EXPECT_THROW(collapsedTriangleRule(0), capsula::core::InputError);
}

} // namespace
