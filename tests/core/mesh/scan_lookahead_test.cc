#include "server/core/mesh/scan_lookahead.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "common/workload.h"

namespace locator {
namespace {

// How many of `queries`, observed in order, get a prediction.
size_t Predicted(const std::vector<Point2>& queries) {
  ScanLookahead lookahead;
  size_t predicted = 0;
  Point2 step;
  for (const Point2& q : queries) predicted += lookahead.Observe(q, &step);
  return predicted;
}

TEST(ScanLookaheadTest, PredictsOnceAStepRepeats) {
  ScanLookahead lookahead;
  Point2 step;
  EXPECT_FALSE(lookahead.Observe({1, 1}, &step));
  EXPECT_FALSE(lookahead.Observe({1.5, 0.75}, &step));
  ASSERT_TRUE(lookahead.Observe({2, 0.5}, &step));
  EXPECT_EQ(step.x, 0.5);
  EXPECT_EQ(step.y, -0.25);
  // A turn breaks the prediction until the new step repeats.
  EXPECT_FALSE(lookahead.Observe({2, 1.5}, &step));
  EXPECT_TRUE(lookahead.Observe({2, 2.5}, &step));
  EXPECT_EQ(step.y, 1);
}

TEST(ScanLookaheadTest, ARowOrderRasterIsPredictedButAtRowStarts) {
  // 300 x 300 queries: in each row, the first two steps differ from the
  // step before them; rounded grid coordinates still count as one step.
  const BoundingBox box{-3.7, 11.1, 1e5 + 0.3, 2e5 / 3};
  EXPECT_EQ(Predicted(RasterQueries(box, 90000)), 300u * 298u);
}

TEST(ScanLookaheadTest, RandomQueriesAreNotPredicted) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(0, 1);
  std::vector<Point2> queries(10000);
  for (Point2& q : queries) q = {coordinate(random), coordinate(random)};
  EXPECT_EQ(Predicted(queries), 0u);
}

TEST(ScanLookaheadTest, ZeroAndNonFiniteStepsAreNotPredicted) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Predicted({{1, 2}, {1, 2}, {1, 2}, {1, 2}}), 0u);
  EXPECT_EQ(Predicted({{nan, 0}, {nan, 1}, {nan, 2}, {nan, 3}}), 0u);
  EXPECT_EQ(Predicted({{0, 0}, {inf, 0}, {inf, 0}, {inf, 0}}), 0u);
  EXPECT_EQ(Predicted({{-1e308, 0}, {1e308, 0}, {-1e308, 0}}), 0u);
}

}  // namespace
}  // namespace locator
