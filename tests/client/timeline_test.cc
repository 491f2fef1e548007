#include "client/load/timeline.h"

#include <gtest/gtest.h>

#include <chrono>
#include <vector>

namespace locator {
namespace {

using std::chrono::milliseconds;

const LoadClock::time_point kOrigin = LoadClock::now();

TEST(TimelineTest, CountsEachCallInTheSliceItEndedIn) {
  Timeline timeline(kOrigin, milliseconds(500));
  const std::vector<uint32_t> costs = {4, 6};
  // Below 128 us the histogram is exact.
  timeline.Record(kOrigin + milliseconds(100), true, 100, costs);
  timeline.Record(kOrigin + milliseconds(499), true, 120, costs);
  timeline.Record(kOrigin + milliseconds(1200), false, 0, {});
  const uint32_t cost = 10;
  timeline.Record(kOrigin + milliseconds(1300), true, 2000, {&cost, 1});

  EXPECT_DOUBLE_EQ(timeline.slice_seconds(), 0.5);
  const std::vector<TimelineSlice> slices = timeline.Slices();
  ASSERT_EQ(slices.size(), 3u);
  EXPECT_EQ(slices[0].calls, 2u);
  EXPECT_EQ(slices[0].p50_us, 100u);
  EXPECT_EQ(slices[0].p99_us, 120u);
  EXPECT_EQ(slices[0].queries, 4u);
  EXPECT_DOUBLE_EQ(slices[0].mean_cost, 5.0);
  // Nothing ended in the second slice: it is listed, empty.
  EXPECT_DOUBLE_EQ(slices[1].start_seconds, 0.5);
  EXPECT_EQ(slices[1].calls, 0u);
  EXPECT_EQ(slices[1].queries, 0u);
  EXPECT_DOUBLE_EQ(slices[1].mean_cost, 0.0);
  EXPECT_EQ(slices[2].calls, 1u);
  EXPECT_EQ(slices[2].failed_calls, 1u);
  EXPECT_DOUBLE_EQ(slices[2].mean_cost, 10.0);
}

TEST(TimelineTest, CallsBeforeTheOriginCountInTheFirstSlice) {
  Timeline timeline(kOrigin, milliseconds(1000));
  timeline.Record(kOrigin - milliseconds(5), true, 10, {});
  const std::vector<TimelineSlice> slices = timeline.Slices();
  ASSERT_EQ(slices.size(), 1u);
  EXPECT_EQ(slices[0].calls, 1u);
}

}  // namespace
}  // namespace locator
