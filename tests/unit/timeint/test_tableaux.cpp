// Butcher tableaux: consistency, the ERRATA weight, and the Runge-Kutta order conditions.
#include "capsula/timeint/ButcherTableau.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace ti = capsula::timeint;

namespace {

using Vector = std::vector<double>;

Vector multiply(const ti::ButcherTableau& t, const Vector& v)
{
  Vector out(static_cast<std::size_t>(t.stages), 0.0);
  for (int i = 0; i < t.stages; ++i) {
    for (int j = 0; j < t.stages; ++j) {
      out[static_cast<std::size_t>(i)] += t.coefficient(i, j) * v[static_cast<std::size_t>(j)];
    }
  }
  return out;
}

Vector times(const Vector& a, const Vector& b)
{
  Vector out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[i] = a[i] * b[i];
  }
  return out;
}

double dot(const Vector& a, const Vector& b)
{
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    s += a[i] * b[i];
  }
  return s;
}

struct OrderCondition {
  int order;
  std::string tree;
  double value;    // sum_i b_i Phi_i(tree)
  double expected; // 1 / gamma(tree)
};

/// The 17 order conditions of the rooted trees with up to 5 nodes (Butcher; Hairer,
/// Norsett & Wanner Table II.2.2), evaluated for the weights `b`.
std::vector<OrderCondition> orderConditions(const ti::ButcherTableau& t, const Vector& b)
{
  const Vector& c = t.c;
  const Vector one(c.size(), 1.0);
  const Vector c2 = times(c, c), c3 = times(c2, c);
  const Vector Ac = multiply(t, c), Ac2 = multiply(t, c2), Ac3 = multiply(t, c3);
  const Vector AAc = multiply(t, Ac), AAc2 = multiply(t, Ac2), AAAc = multiply(t, AAc);
  const Vector AcAc = multiply(t, times(c, Ac));
  return {
      {1, "t", dot(b, one), 1.0},
      {2, "[t]", dot(b, c), 1.0 / 2},
      {3, "[t,t]", dot(b, c2), 1.0 / 3},
      {3, "[[t]]", dot(b, Ac), 1.0 / 6},
      {4, "[t,t,t]", dot(b, c3), 1.0 / 4},
      {4, "[t,[t]]", dot(b, times(c, Ac)), 1.0 / 8},
      {4, "[[t,t]]", dot(b, Ac2), 1.0 / 12},
      {4, "[[[t]]]", dot(b, AAc), 1.0 / 24},
      {5, "[t,t,t,t]", dot(b, times(c2, c2)), 1.0 / 5},
      {5, "[t,t,[t]]", dot(b, times(c2, Ac)), 1.0 / 10},
      {5, "[[t],[t]]", dot(b, times(Ac, Ac)), 1.0 / 20},
      {5, "[t,[t,t]]", dot(b, times(c, Ac2)), 1.0 / 15},
      {5, "[t,[[t]]]", dot(b, times(c, AAc)), 1.0 / 30},
      {5, "[[t,t,t]]", dot(b, Ac3), 1.0 / 20},
      {5, "[[t,[t]]]", dot(b, AcAc), 1.0 / 40},
      {5, "[[[t,t]]]", dot(b, AAc2), 1.0 / 60},
      {5, "[[[[t]]]]", dot(b, AAAc), 1.0 / 120},
  };
}

// Coefficients are ratios of integers up to ~3e5 rounded to doubles; the sums of products
// of up to five of them (entries up to ~12 in magnitude) carry a few 1e-15 of rounding.
constexpr double orderConditionTolerance = 5e-14;

void expectOrder(const ti::ButcherTableau& t, const Vector& b, int order, const std::string& what)
{
  bool someHigherConditionFails = false;
  for (const auto& condition : orderConditions(t, b)) {
    if (condition.order <= order) {
      EXPECT_NEAR(condition.value, condition.expected, orderConditionTolerance)
          << t.name << " " << what << ": order condition of tree " << condition.tree;
    } else if (condition.order == order + 1 && std::abs(condition.value - condition.expected) > 1e-6) {
      someHigherConditionFails = true;
    }
  }
  if (order < 5) {
    // The weights are of order exactly `order`, not accidentally higher.
    EXPECT_TRUE(someHigherConditionFails) << t.name << " " << what;
  }
}

void expectConsistentStages(const ti::ButcherTableau& t)
{
  ASSERT_EQ(t.a.size(), static_cast<std::size_t>(t.stages * t.stages));
  ASSERT_EQ(t.c.size(), static_cast<std::size_t>(t.stages));
  for (int i = 0; i < t.stages; ++i) {
    double rowSum = 0.0;
    for (int j = 0; j < t.stages; ++j) {
      if (j >= i) {
        EXPECT_EQ(t.coefficient(i, j), 0.0) << t.name << ": explicit methods have a_ij = 0 for j >= i";
      }
      rowSum += t.coefficient(i, j);
    }
    // c_i = sum_j a_ij to rounding of a handful of O(10) terms.
    EXPECT_NEAR(rowSum, t.c[static_cast<std::size_t>(i)], 1e-15 * 16) << t.name << " stage " << i + 1;
  }
}

} // namespace

TEST(ButcherTableau, RKF45StagesAreConsistent)
{
  expectConsistentStages(ti::rungeKuttaFehlberg45());
}

TEST(ButcherTableau, RKF45WeightsSumToOneWithTheErrataFix)
{
  const auto t = ti::rungeKuttaFehlberg45();
  double sum4 = 0.0, sum5 = 0.0;
  for (int i = 0; i < t.stages; ++i) {
    sum4 += t.b[static_cast<std::size_t>(i)];
    sum5 += t.bEmbedded[static_cast<std::size_t>(i)];
  }
  // Six rounded weights: a few ulps. The printed 2197/4101 would be off by 3.9e-4.
  EXPECT_NEAR(sum4, 1.0, 1e-15 * 4);
  EXPECT_NEAR(sum5, 1.0, 1e-15 * 4);
  EXPECT_EQ(t.b[3], 2197.0 / 4104);
  EXPECT_GT(std::abs(2197.0 / 4101 - 2197.0 / 4104), 1e-4);
}

TEST(ButcherTableau, RKF45FourthAndFifthOrderWeightsSatisfyTheirOrderConditions)
{
  const auto t = ti::rungeKuttaFehlberg45();
  EXPECT_EQ(t.order, 4);
  EXPECT_EQ(t.embeddedOrder, 5);
  expectOrder(t, t.b, 4, "4th-order weights (eq 3.48)");
  expectOrder(t, t.bEmbedded, 5, "5th-order weights (eq 3.49)");
}

TEST(ButcherTableau, RKF45LocalExtrapolationSwapsTheSolutions)
{
  const auto t = ti::rungeKuttaFehlberg45();
  const auto x = ti::rungeKuttaFehlberg45Extrapolated();
  EXPECT_EQ(x.order, 5);
  EXPECT_EQ(x.b, t.bEmbedded);
  EXPECT_EQ(x.bEmbedded, t.b);
  expectOrder(x, x.b, 5, "advancing weights");
}

TEST(ButcherTableau, DormandPrince45IsFifthOrderWithFourthOrderEmbeddedAndFsal)
{
  const auto t = ti::dormandPrince45();
  expectConsistentStages(t);
  expectOrder(t, t.b, 5, "5th-order weights");
  expectOrder(t, t.bEmbedded, 4, "embedded 4th-order weights");
  ASSERT_TRUE(t.firstSameAsLast);
  // FSAL: the last stage is evaluated at (t + h, y_new).
  EXPECT_EQ(t.c.back(), 1.0);
  EXPECT_EQ(t.b.back(), 0.0);
  for (int j = 0; j < t.stages; ++j) {
    EXPECT_EQ(t.coefficient(t.stages - 1, j), t.b[static_cast<std::size_t>(j)]);
  }
}

TEST(ButcherTableau, ClassicalRungeKutta4IsFourthOrder)
{
  const auto t = ti::classicalRungeKutta4();
  expectConsistentStages(t);
  expectOrder(t, t.b, 4, "weights");
  EXPECT_FALSE(t.hasErrorEstimate());
}
