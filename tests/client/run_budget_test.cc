#include "client/load/run_budget.h"

#include <gtest/gtest.h>

namespace locator {
namespace {

using std::chrono::milliseconds;

TEST(RunBudgetTest, TimedRunMarksTheWarmupAndEnds) {
  const LoadClock::time_point start = LoadClock::now();
  RunBudget budget(RunLength{.warmup_seconds = 1, .measured_seconds = 2},
                   start);
  Claim claim;
  ASSERT_TRUE(budget.TryClaim(10, start + milliseconds(500), &claim));
  EXPECT_TRUE(claim.warmup);
  EXPECT_EQ(claim.points, 10u);
  ASSERT_TRUE(budget.TryClaim(10, start + milliseconds(1500), &claim));
  EXPECT_FALSE(claim.warmup);
  EXPECT_FALSE(budget.TryClaim(10, start + milliseconds(3000), &claim));
  EXPECT_EQ(budget.measure_start(), start + milliseconds(1000));
  EXPECT_EQ(budget.end(), start + milliseconds(3000));
}

TEST(RunBudgetTest, CountedRunGrantsExactlyTheQueries) {
  const LoadClock::time_point start = LoadClock::now();
  RunBudget budget(RunLength{.warmup_queries = 4, .measured_queries = 10},
                   start);
  Claim claim;
  ASSERT_TRUE(budget.TryClaim(5, start, &claim));
  EXPECT_TRUE(claim.warmup);  // straddles the warm-up's end: counts as it
  ASSERT_TRUE(budget.TryClaim(5, start + milliseconds(1), &claim));
  EXPECT_FALSE(claim.warmup);
  EXPECT_EQ(budget.measure_start(), start + milliseconds(1));
  ASSERT_TRUE(budget.TryClaim(5, start + milliseconds(2), &claim));
  EXPECT_EQ(claim.points, 4u);  // 14 in all
  EXPECT_FALSE(budget.TryClaim(5, start + milliseconds(3), &claim));
}

TEST(RunBudgetTest, CountedRunStopsAtTheTimeLimit) {
  const LoadClock::time_point start = LoadClock::now();
  RunBudget budget(
      RunLength{.measured_queries = 1'000'000, .time_limit_seconds = 1}, start);
  Claim claim;
  EXPECT_TRUE(budget.TryClaim(1, start, &claim));
  EXPECT_FALSE(budget.TryClaim(1, start + milliseconds(1000), &claim));
  EXPECT_EQ(budget.end(), start + milliseconds(1000));
}

}  // namespace
}  // namespace locator
