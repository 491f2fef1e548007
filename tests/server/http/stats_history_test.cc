#include "server/http/status/stats_history.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

namespace locator {
namespace {

using std::chrono::seconds;
using std::chrono::system_clock;

const system_clock::time_point kStart = system_clock::time_point(seconds(1000));

TEST(StatsHistoryTest, SamplesAreRatesOverEachInterval) {
  StatsHistory history;
  history.Record(1, 100, 1000, kStart);
  EXPECT_TRUE(history.Samples().empty());  // a baseline, no interval yet
  history.Record(1, 300, 1800, kStart + seconds(2));
  history.Record(1, 300, 1800, kStart + seconds(3));
  const auto samples = history.Samples();
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[0].unix_seconds, 1002);
  EXPECT_EQ(samples[0].qps, 100);      // 200 queries in 2 s
  EXPECT_EQ(samples[0].mean_cost, 4);  // 800 cost / 200 queries
  EXPECT_EQ(samples[1].qps, 0);
  EXPECT_TRUE(std::isnan(samples[1].mean_cost));
}

TEST(StatsHistoryTest, ANewEngineCountsFromZero) {
  StatsHistory history;
  history.Record(1, 5000, 50000, kStart);
  history.Record(2, 10, 30, kStart + seconds(1));
  // Same address reused, but the counters went backwards.
  history.Record(2, 4, 8, kStart + seconds(2));
  const auto samples = history.Samples();
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[0].qps, 10);
  EXPECT_EQ(samples[0].mean_cost, 3);
  EXPECT_EQ(samples[1].qps, 4);
  EXPECT_EQ(samples[1].mean_cost, 2);
}

TEST(StatsHistoryTest, KeepsTheLastCapacitySamples) {
  StatsHistory history;
  for (size_t i = 0; i <= StatsHistory::kCapacity + 10; ++i) {
    history.Record(1, i, i, kStart + seconds(i));
  }
  const auto samples = history.Samples();
  ASSERT_EQ(samples.size(), StatsHistory::kCapacity);
  EXPECT_EQ(samples.front().unix_seconds, 1011);
  EXPECT_EQ(samples.back().unix_seconds, 1000 + StatsHistory::kCapacity + 10);
}

}  // namespace
}  // namespace locator
