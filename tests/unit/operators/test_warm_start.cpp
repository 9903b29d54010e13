// WarmStartHistory: the least-squares combination of the last solutions that starts the
// next GMRES solve of a time integration (WarmStartHistory.hpp).
#include <capsula/core/Error.hpp>
#include <capsula/operators/WarmStartHistory.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using capsula::operators::WarmStartHistory;

// b_j and u_j = M b_j for a fixed "inverse" M (here diag(1 + k / 10)), as if the operator
// had not changed between solves.
std::vector<double> applyM(const std::vector<double>& b)
{
  std::vector<double> u(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) {
    u[k] = (1.0 + 0.1 * static_cast<double>(k)) * b[k];
  }
  return u;
}

std::vector<double> vectorOf(double a, double b, double c)
{
  std::vector<double> v(12);
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double x = static_cast<double>(k);
    v[k] = a * std::sin(x) + b * std::cos(0.5 * x) + c * x * x;
  }
  return v;
}

TEST(WarmStartHistory, EmptyHistoryStartsFromTheRightHandSide)
{
  const WarmStartHistory history;
  EXPECT_TRUE(history.empty());
  const auto b = vectorOf(1.0, 2.0, 0.1);
  EXPECT_EQ(history.initialGuess(b), b);
}

TEST(WarmStartHistory, RightHandSideInTheSpanGivesTheExactSolution)
{
  // With an unchanged operator the guess is exact when b is a combination of the b_j (an
  // RK stage is a combination of earlier slopes), whatever the combination.
  WarmStartHistory history(3);
  for (const auto& b : {vectorOf(1.0, 0.0, 0.0), vectorOf(0.0, 1.0, 0.0), vectorOf(0.0, 0.0, 1.0)}) {
    history.add(b, applyM(b));
  }
  const auto b = vectorOf(0.3, -1.7, 0.05);
  const auto guess = history.initialGuess(b);
  const auto exact = applyM(b);
  for (std::size_t k = 0; k < b.size(); ++k) {
    // Round-off of a 12 x 3 least-squares solve with entries up to ~120 (c x^2): 1e-12
    // relative to the largest entry leaves room for its conditioning (~1e2).
    EXPECT_NEAR(guess[k], exact[k], 1e-12 * 130.0) << k;
  }
  // Two pairs are enough for a b in their span.
  WarmStartHistory two(2);
  two.add(vectorOf(1.0, 0.0, 0.0), applyM(vectorOf(1.0, 0.0, 0.0)));
  two.add(vectorOf(0.0, 1.0, 0.0), applyM(vectorOf(0.0, 1.0, 0.0)));
  const auto partial = two.initialGuess(vectorOf(0.3, -1.7, 0.0));
  const auto partialExact = applyM(vectorOf(0.3, -1.7, 0.0));
  for (std::size_t k = 0; k < partial.size(); ++k) {
    EXPECT_NEAR(partial[k], partialExact[k], 1e-13) << k; // entries ~2, round-off
  }
}

TEST(WarmStartHistory, KeepsTheLastPairsAndRoundTripsThroughItsFlatForm)
{
  WarmStartHistory history(2);
  for (int j = 0; j < 4; ++j) {
    const auto b = vectorOf(1.0, static_cast<double>(j), 0.0);
    history.add(b, applyM(b));
  }
  EXPECT_EQ(history.size(), 2);
  const std::vector<double> rhs = history.rightHandSides();
  ASSERT_EQ(rhs.size(), 24u);
  const auto third = vectorOf(1.0, 2.0, 0.0); // the oldest kept
  EXPECT_EQ(std::vector<double>(rhs.begin(), rhs.begin() + 12), third);
  const WarmStartHistory copy = WarmStartHistory::fromFlattened(2, 12, rhs, history.solutions());
  EXPECT_EQ(copy.rightHandSides(), rhs);
  EXPECT_EQ(copy.solutions(), history.solutions());
  const auto b = vectorOf(0.2, 0.4, 0.0);
  EXPECT_EQ(copy.initialGuess(b), history.initialGuess(b)); // bit for bit: a restart
}

TEST(WarmStartHistory, MismatchedInputIsRejected)
{
  EXPECT_THROW(WarmStartHistory(0), capsula::core::InputError);
  WarmStartHistory history;
  EXPECT_THROW(history.add(std::vector<double>(3), std::vector<double>(4)), capsula::core::InputError);
  history.add(std::vector<double>(3, 1.0), std::vector<double>(3, 1.0));
  EXPECT_THROW(history.add(std::vector<double>(6), std::vector<double>(6)), capsula::core::InputError);
  EXPECT_THROW(WarmStartHistory::fromFlattened(6, 5, std::vector<double>(12), std::vector<double>(12)),
               capsula::core::InputError);
  EXPECT_THROW(WarmStartHistory::fromFlattened(1, 6, std::vector<double>(12), std::vector<double>(12)),
               capsula::core::InputError);
}

} // namespace
