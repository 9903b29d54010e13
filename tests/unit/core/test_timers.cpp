// Timers named by their owners: a run lists every one that ran (core::timerTotals).
#include <capsula/core/Timers.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace core = capsula::core;

namespace {

const core::TimerTotal* find(const std::vector<core::TimerTotal>& totals, const std::string& name)
{
  const auto it = std::find_if(totals.begin(), totals.end(), [&](const auto& t) { return t.name == name; });
  return it == totals.end() ? nullptr : &*it;
}

} // namespace

TEST(Timers, TotalsListTheTimersThatRanByTheirOwnersNames)
{
  const auto used = core::timer("test: used twice");
  core::timer("test: never started");
  for (int k = 0; k < 2; ++k) {
    Teuchos::TimeMonitor guard(*used);
  }
  const auto totals = core::timerTotals();
  const core::TimerTotal* ran = find(totals, "test: used twice");
  ASSERT_NE(ran, nullptr); // named without the "Capsula: " prefix
  EXPECT_EQ(ran->calls, 2);
  EXPECT_GE(ran->seconds, 0.0);
  EXPECT_EQ(find(totals, "test: never started"), nullptr);
  // Teuchos's own timers (not made by core::timer) are not Capsula's.
  Teuchos::TimeMonitor::getNewCounter("not ours");
  for (const auto& total : core::timerTotals()) {
    EXPECT_NE(total.name, "not ours");
  }
}
