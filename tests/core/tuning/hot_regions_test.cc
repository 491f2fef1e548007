#include "server/core/tuning/hot_regions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace locator {
namespace {

// 16 x 16 unit cells over [0, 16]^2, so cell (c, r) is [c, c+1] x [r, r+1].
constexpr int kSize = 16;
const GridGeometry kGrid(BoundingBox{0, 0, kSize, kSize}, kSize);

// Histogram counts, `background` everywhere.
class Counts {
 public:
  explicit Counts(double background = 0) : counts_(kSize * kSize, background) {}
  // Sets columns [c0, c1] x rows [r0, r1] to `count`.
  Counts& Block(int c0, int r0, int c1, int r1, double count) {
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) counts_[r * kSize + c] = count;
    }
    return *this;
  }
  const std::vector<double>& get() const { return counts_; }

 private:
  std::vector<double> counts_;
};

BoundingBox CellsBox(int c0, int r0, int c1, int r1) {
  return BoundingBox{double(c0), double(r0), double(c1 + 1), double(r1 + 1)};
}

bool SameBox(const BoundingBox& a, const BoundingBox& b) {
  return a.min_x == b.min_x && a.min_y == b.min_y && a.max_x == b.max_x &&
         a.max_y == b.max_y;
}

bool HasBox(const std::vector<BoundingBox>& boxes, const BoundingBox& b) {
  return std::any_of(boxes.begin(), boxes.end(),
                     [&b](const BoundingBox& x) { return SameBox(x, b); });
}

bool CoveredByAny(const std::vector<BoundingBox>& boxes, const Point2& p) {
  return std::any_of(boxes.begin(), boxes.end(),
                     [&p](const BoundingBox& b) { return b.Contains(p); });
}

TEST(FindHotRegionsTest, UniformCountsHaveNoRegions) {
  EXPECT_TRUE(FindHotRegions(kGrid, Counts(50).get()).empty());
  EXPECT_TRUE(FindHotRegions(kGrid, Counts(0).get()).empty());
}

TEST(FindHotRegionsTest, SingleHotBlockIsCoveredExactly) {
  const auto regions =
      FindHotRegions(kGrid, Counts(1).Block(3, 7, 5, 8, 100).get());
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(SameBox(regions[0], CellsBox(3, 7, 5, 8)));
}

TEST(FindHotRegionsTest, SingleHotCell) {
  const auto regions =
      FindHotRegions(kGrid, Counts().Block(15, 0, 15, 0, 10).get());
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(SameBox(regions[0], CellsBox(15, 0, 15, 0)));
}

TEST(FindHotRegionsTest, ThreeSeparatedBlocksGiveThreeRectangles) {
  Counts counts(1);
  counts.Block(1, 1, 2, 2, 80).Block(10, 3, 12, 3, 80).Block(5, 12, 5, 14, 80);
  const auto regions = FindHotRegions(kGrid, counts.get());
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_TRUE(HasBox(regions, CellsBox(1, 1, 2, 2)));
  EXPECT_TRUE(HasBox(regions, CellsBox(10, 3, 12, 3)));
  EXPECT_TRUE(HasBox(regions, CellsBox(5, 12, 5, 14)));
}

TEST(FindHotRegionsTest, DiagonalBandMergesIntoAtMostMaxRegions) {
  Counts counts(1);
  std::vector<Point2> hot_centres;
  for (int i = 0; i < kSize; ++i) {
    for (int r = std::max(0, i - 1); r <= std::min(kSize - 1, i + 1); ++r) {
      counts.Block(i, r, i, r, 40);
      hot_centres.push_back({i + 0.5, r + 0.5});
    }
  }
  HotRegionOptions options;
  options.max_regions = 4;
  const auto regions = FindHotRegions(kGrid, counts.get(), options);
  EXPECT_GE(regions.size(), 1u);
  EXPECT_LE(regions.size(), 4u);
  for (const Point2& p : hot_centres) {
    EXPECT_TRUE(CoveredByAny(regions, p)) << p.x << ", " << p.y;
  }
  // Merging keeps to the band rather than the whole grid.
  double area = 0;
  for (const BoundingBox& b : regions) area += b.width() * b.height();
  EXPECT_LT(area, kSize * kSize / 2.0);

  // Without the limit every rectangle holds only hot cells.
  HotRegionOptions unlimited;
  unlimited.max_regions = 1000;
  const auto exact = FindHotRegions(kGrid, counts.get(), unlimited);
  double exact_area = 0;
  for (const BoundingBox& b : exact) exact_area += b.width() * b.height();
  EXPECT_EQ(exact_area, double(hot_centres.size()));
}

TEST(FindHotRegionsTest, MinCountIsRespected) {
  // One cell with 2 queries is far above the mean but below min_count = 3.
  const Counts two = Counts().Block(4, 4, 4, 4, 2);
  EXPECT_TRUE(FindHotRegions(kGrid, two.get()).empty());
  const Counts three = Counts().Block(4, 4, 4, 4, 3);
  const auto regions = FindHotRegions(kGrid, three.get());
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(SameBox(regions[0], CellsBox(4, 4, 4, 4)));

  HotRegionOptions strict;
  strict.min_count = 50;
  const Counts block = Counts().Block(0, 0, 1, 1, 40).Block(9, 9, 9, 9, 60);
  const auto only_big = FindHotRegions(kGrid, block.get(), strict);
  ASSERT_EQ(only_big.size(), 1u);
  EXPECT_TRUE(SameBox(only_big[0], CellsBox(9, 9, 9, 9)));
}

TEST(FindHotRegionsTest, DensityFactorIsRespected) {
  // Mean is about 1.5 per cell: 5 is hot at factor 3 but not at factor 4.
  const Counts counts = Counts(1).Block(7, 7, 8, 8, 5).Block(0, 0, 0, 0, 116);
  HotRegionOptions options;
  options.min_count = 0;
  options.density_factor = 4;
  EXPECT_FALSE(HasBox(FindHotRegions(kGrid, counts.get(), options),
                      CellsBox(7, 7, 8, 8)));
  options.density_factor = 3;
  EXPECT_TRUE(HasBox(FindHotRegions(kGrid, counts.get(), options),
                     CellsBox(7, 7, 8, 8)));
}

}  // namespace
}  // namespace locator
