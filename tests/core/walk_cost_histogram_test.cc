#include "server/core/walk_cost_histogram.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace locator {
namespace {

LocateResult WithFaces(uint32_t faces) {
  LocateResult r;
  r.cost.faces_visited = faces;
  return r;
}

TEST(WalkCostHistogramTest, BucketsAreUpperInclusive) {
  WalkCostHistogram histogram;
  for (uint32_t faces : {0u, 1u, 2u, 5u, 6u, 7u, 16384u, 16385u, 1u << 30}) {
    histogram.Add(faces);
  }
  const WalkCostCounts counts = histogram.Counts();
  ASSERT_EQ(counts.upper_bounds.size(), WalkCostHistogram::kUpperBounds.size());
  ASSERT_EQ(counts.counts.size(), counts.upper_bounds.size() + 1);
  EXPECT_EQ(counts.counts[0], 2u);  // 0 and 1 faces: <= 1
  EXPECT_EQ(counts.counts[1], 1u);  // 2
  EXPECT_EQ(counts.counts[4], 2u);  // 5 and 6: (4, 6]
  EXPECT_EQ(counts.counts[5], 1u);  // 7: (6, 8]
  EXPECT_EQ(counts.counts[counts.upper_bounds.size() - 1], 1u);  // 16384
  EXPECT_EQ(counts.counts.back(), 2u);  // beyond every bound
  EXPECT_EQ(counts.faces_sum,
            0u + 1 + 2 + 5 + 6 + 7 + 16384 + 16385 + (uint64_t{1} << 30));
}

TEST(WalkCostHistogramTest, AddAllEqualsAddingOneByOne) {
  std::vector<LocateResult> results;
  WalkCostHistogram one_by_one;
  for (uint32_t faces = 0; faces < 3000; faces += 7) {
    results.push_back(WithFaces(faces));
    one_by_one.Add(faces);
  }
  WalkCostHistogram all;
  all.AddAll(results);
  EXPECT_EQ(all.Counts().counts, one_by_one.Counts().counts);
  EXPECT_EQ(all.Counts().faces_sum, one_by_one.Counts().faces_sum);
}

}  // namespace
}  // namespace locator
