#include "client/load/latency_histogram.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace locator {
namespace {

TEST(LatencyHistogramTest, EmptyReportsZeros) {
  LatencyHistogram histogram;
  EXPECT_EQ(histogram.count(), 0u);
  EXPECT_EQ(histogram.Percentile(50), 0u);
  EXPECT_EQ(histogram.min(), 0u);
  EXPECT_EQ(histogram.max(), 0u);
  EXPECT_EQ(histogram.mean(), 0.0);
}

TEST(LatencyHistogramTest, SmallValuesAreExact) {
  LatencyHistogram histogram;
  for (uint64_t micros = 1; micros <= 100; ++micros) histogram.Record(micros);
  EXPECT_EQ(histogram.count(), 100u);
  EXPECT_EQ(histogram.Percentile(50), 50u);
  EXPECT_EQ(histogram.Percentile(90), 90u);
  EXPECT_EQ(histogram.Percentile(99), 99u);
  EXPECT_EQ(histogram.Percentile(99.9), 100u);
  EXPECT_EQ(histogram.Percentile(100), 100u);
  EXPECT_EQ(histogram.min(), 1u);
  EXPECT_EQ(histogram.max(), 100u);
  EXPECT_DOUBLE_EQ(histogram.mean(), 50.5);
}

TEST(LatencyHistogramTest, LargeValuesAreWithinOneBucketAbove) {
  for (uint64_t micros : {uint64_t{129}, uint64_t{1000}, uint64_t{12'345},
                          uint64_t{999'999}, uint64_t{3'600'000'000}}) {
    LatencyHistogram histogram;
    histogram.Record(micros);
    histogram.Record(2 * micros);  // so the percentile is not capped by max
    const uint64_t median = histogram.Percentile(50);
    EXPECT_GE(median, micros);
    EXPECT_LE(median, micros + micros / 64) << micros;
  }
}

TEST(LatencyHistogramTest, PercentileIsCappedAtMax) {
  LatencyHistogram histogram;
  histogram.Record(1000);
  EXPECT_EQ(histogram.Percentile(50), 1000u);
  EXPECT_EQ(histogram.Percentile(100), 1000u);
}

TEST(LatencyHistogramTest, HugeValuesLandInTheLastBucket) {
  LatencyHistogram histogram;
  histogram.Record(UINT64_MAX / 2);
  EXPECT_EQ(histogram.count(), 1u);
  EXPECT_EQ(histogram.max(), UINT64_MAX / 2);
  EXPECT_GT(histogram.Percentile(100), uint64_t{1} << 36);
}

TEST(LatencyHistogramTest, TailPercentilesOfASkewedRun) {
  // 990 fast calls of 100 us and 10 slow ones of 50 ms.
  LatencyHistogram histogram;
  for (int i = 0; i < 990; ++i) histogram.Record(100);
  for (int i = 0; i < 10; ++i) histogram.Record(50'000);
  EXPECT_EQ(histogram.Percentile(50), 100u);
  EXPECT_EQ(histogram.Percentile(99), 100u);
  EXPECT_GE(histogram.Percentile(99.9), 50'000u);
  EXPECT_EQ(histogram.max(), 50'000u);
}

TEST(LatencyHistogramTest, MergeEqualsRecordingEverythingInOne) {
  LatencyHistogram fast, slow, all;
  for (uint64_t micros = 1; micros <= 500; ++micros) {
    fast.Record(micros);
    all.Record(micros);
    slow.Record(micros * 1000);
    all.Record(micros * 1000);
  }
  fast.Merge(slow);
  EXPECT_EQ(fast.count(), all.count());
  EXPECT_EQ(fast.min(), all.min());
  EXPECT_EQ(fast.max(), all.max());
  EXPECT_DOUBLE_EQ(fast.mean(), all.mean());
  for (double percent : {1.0, 25.0, 50.0, 75.0, 99.0, 99.9, 100.0}) {
    EXPECT_EQ(fast.Percentile(percent), all.Percentile(percent)) << percent;
  }
}

}  // namespace
}  // namespace locator
