#include "common/gis/crs_transformer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>
#include <vector>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"

namespace locator::gis {
namespace {

using ::testing::HasSubstr;

// Lon/lat points in UTM zone 33N's area of use (12°E..18°E).
std::vector<Point2> LonLatPoints() {
  std::vector<Point2> points;
  for (int i = 0; i < 20; ++i) {
    points.push_back({12.5 + 0.25 * i, 40.0 + 1.7 * i});
  }
  return points;
}

TEST(CrsTransformerTest, MatchesCs2csToAMicrometre) {
  test::ScratchDir dir;
  const std::vector<Point2> lon_lat = LonLatPoints();
  // cs2cs honours EPSG:4326's authority axis order: latitude first.
  std::ostringstream input;
  input.precision(17);
  for (const Point2& p : lon_lat) input << p.y << " " << p.x << "\n";
  const std::string input_path = dir.path() + "/lat_lon.txt";
  testing::WriteFile(input_path, input.str());
  const std::string output = testing::RunTool(
      CS2CS_PATH, {"-f", "%.9f", "EPSG:4326", "EPSG:32633", input_path});

  std::vector<Point2> projected = lon_lat;
  StatusOr<std::unique_ptr<CrsTransformer>> created =
      CrsTransformer::Create("EPSG:4326", "EPSG:32633");
  ASSERT_TRUE(created.ok()) << created.status().ToString();
  const std::unique_ptr<CrsTransformer> transformer = *std::move(created);
  ASSERT_TRUE(transformer->ToDataset(projected).ok());
  std::istringstream lines(output);
  for (const Point2& p : projected) {
    double easting, northing, height;
    ASSERT_TRUE(lines >> easting >> northing >> height) << output;
    EXPECT_NEAR(p.x, easting, 1e-6);
    EXPECT_NEAR(p.y, northing, 1e-6);
  }
}

TEST(CrsTransformerTest, RoundTripsAndAgreesWithTheInverse) {
  const StatusOr<std::unique_ptr<CrsTransformer>> forward =
      CrsTransformer::Create("EPSG:4326", "EPSG:32633");
  ASSERT_TRUE(forward.ok());
  const StatusOr<std::unique_ptr<CrsTransformer>> backward =
      CrsTransformer::Create("EPSG:32633", "EPSG:4326");
  ASSERT_TRUE(backward.ok());
  const std::vector<Point2> original = LonLatPoints();
  std::vector<Point2> utm = original;
  ASSERT_TRUE((*forward)->ToDataset(utm).ok());
  std::vector<Point2> via_inverse = utm;
  ASSERT_TRUE((*forward)->ToRequest(via_inverse).ok());
  std::vector<Point2> via_backward = utm;
  ASSERT_TRUE((*backward)->ToDataset(via_backward).ok());
  for (size_t i = 0; i < original.size(); ++i) {
    EXPECT_GT(utm[i].x, 100000);  // x is the easting, not the latitude
    EXPECT_NEAR(via_inverse[i].x, original[i].x, 1e-10);
    EXPECT_NEAR(via_inverse[i].y, original[i].y, 1e-10);
    EXPECT_NEAR(via_backward[i].x, original[i].x, 1e-10);
    EXPECT_NEAR(via_backward[i].y, original[i].y, 1e-10);
  }
}

TEST(CrsTransformerTest, PointOutsideTheAreaOfUseIsNamedByIndex) {
  StatusOr<std::unique_ptr<CrsTransformer>> created =
      CrsTransformer::Create("EPSG:4326", "EPSG:32633");
  ASSERT_TRUE(created.ok()) << created.status().ToString();
  const std::unique_ptr<CrsTransformer> transformer = *std::move(created);
  std::vector<Point2> points = {{15, 45}, {16, 50}, {40, 10}};
  const Status status = transformer->ToDataset(points);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(),
              HasSubstr("point 2 (40, 10) is outside the area of use of the "
                        "transformation from 'EPSG:4326' to 'EPSG:32633'"));
  // A block of a larger request names the point by its index there.
  std::vector<Point2> block = {{16, 50}, {40, 10}};
  EXPECT_THAT(transformer->ToDataset(block, /*first_index=*/8192).message(),
              HasSubstr("point 8193 (40, 10) is outside the area of use"));
  // Coordinates in shortest form, not 17 digits of 1e300's double.
  std::vector<Point2> huge = {{0.1, 1e300}};
  EXPECT_THAT(transformer->ToDataset(huge).message(),
              HasSubstr("point 0 (0.1, 1e+300) is outside the area of use"));
  // Non-finite points are left for the caller's check.
  std::vector<Point2> nan_point = {{std::nan(""), 45}};
  EXPECT_TRUE(transformer->ToDataset(nan_point).ok());
  EXPECT_TRUE(std::isnan(nan_point[0].x));
  EXPECT_EQ(nan_point[0].y, 45);
}

TEST(CrsTransformerTest, UnknownCrsIsInvalidArgument) {
  Status status = CrsTransformer::Create("EPSG:999999", "EPSG:32633").status();
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("unknown CRS 'EPSG:999999'"));
  CrsTransformer* cached = nullptr;
  status = CrsTransformer::ForThread("EPSG:4326", "bogus", &cached);
  EXPECT_THAT(status.message(), HasSubstr("unknown CRS 'bogus'"));
}

TEST(CrsTransformerTest, PerThreadCacheSharesWithinAThreadOnly) {
  CrsTransformer* first = nullptr;
  CrsTransformer* again = nullptr;
  ASSERT_TRUE(
      CrsTransformer::ForThread("EPSG:4326", "EPSG:32633", &first).ok());
  ASSERT_TRUE(
      CrsTransformer::ForThread("EPSG:4326", "EPSG:32633", &again).ok());
  EXPECT_EQ(first, again);

  std::vector<Point2> expected = LonLatPoints();
  ASSERT_TRUE(first->ToDataset(expected).ok());
  constexpr int kThreads = 4;
  constexpr int kRounds = 200;
  std::vector<CrsTransformer*> used(kThreads, nullptr);
  std::vector<int> mismatches(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int round = 0; round < kRounds; ++round) {
        // Interleave another pair so the cache holds two entries.
        CrsTransformer* other = nullptr;
        if (!CrsTransformer::ForThread("EPSG:4326", "EPSG:32632", &other)
                 .ok()) {
          ++mismatches[t];
        }
        CrsTransformer* transformer = nullptr;
        std::vector<Point2> points = LonLatPoints();
        if (!CrsTransformer::ForThread("EPSG:4326", "EPSG:32633", &transformer)
                 .ok() ||
            !transformer->ToDataset(points).ok()) {
          ++mismatches[t];
          continue;
        }
        if (used[t] == nullptr) used[t] = transformer;
        if (used[t] != transformer) ++mismatches[t];
        for (size_t i = 0; i < points.size(); ++i) {
          if (points[i].x != expected[i].x || points[i].y != expected[i].y) {
            ++mismatches[t];
          }
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) {
    EXPECT_EQ(mismatches[t], 0) << "thread " << t;
    EXPECT_NE(used[t], first) << "thread " << t << " used the main thread's";
  }
}

TEST(CrsTransformerTest, CacheEvictsBeyondItsCapacityAndStillWorks) {
  // UTM zones 1..20 north: more pairs than the cache holds.
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t zone = 1; zone <= CrsTransformer::kCacheCapacity + 4; ++zone) {
      CrsTransformer* transformer = nullptr;
      const std::string utm = "EPSG:" + std::to_string(32600 + zone);
      ASSERT_TRUE(
          CrsTransformer::ForThread(utm, "EPSG:4326", &transformer).ok());
      std::vector<Point2> points = {{500000, 0}};
      ASSERT_TRUE(transformer->ToDataset(points).ok());
      EXPECT_NEAR(points[0].x, -183.0 + 6.0 * zone, 1e-9) << utm;
      EXPECT_NEAR(points[0].y, 0, 1e-9);
    }
  }
}

}  // namespace
}  // namespace locator::gis
