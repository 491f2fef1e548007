#include "server/core/tuning/query_histogram.h"

#include <gtest/gtest.h>

#include <atomic>
#include <limits>
#include <numeric>
#include <thread>
#include <vector>

namespace locator {
namespace {

// 10 x 10 cells of 1 x 2 units over [0, 10] x [0, 20].
const BoundingBox kBox{0, 0, 10, 20};

size_t Cell(int column, int row) { return size_t(row) * 10 + column; }

double Sum(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

TEST(GridGeometryTest, MapsCornersAndInteriorRowMajor) {
  const GridGeometry grid(kBox, 10);
  EXPECT_EQ(grid.size(), 10);
  EXPECT_EQ(grid.cells(), 100u);
  EXPECT_EQ(grid.CellOf({0, 0}), Cell(0, 0));
  EXPECT_EQ(grid.CellOf({10, 0}), Cell(9, 0));
  EXPECT_EQ(grid.CellOf({0, 20}), Cell(0, 9));
  EXPECT_EQ(grid.CellOf({10, 20}), Cell(9, 9));
  EXPECT_EQ(grid.CellOf({5.5, 7}), Cell(5, 3));
  EXPECT_EQ(grid.CellOf({1, 2}), Cell(1, 1));  // lower cell edges belong in
  EXPECT_EQ(grid.CellOf({0.999, 1.999}), Cell(0, 0));
  EXPECT_DOUBLE_EQ(grid.cell_width(), 1);
  EXPECT_DOUBLE_EQ(grid.cell_height(), 2);
}

TEST(GridGeometryTest, OutsidePointsClampToTheNearestCell) {
  const GridGeometry grid(kBox, 10);
  EXPECT_EQ(grid.CellOf({-5, 25}), Cell(0, 9));
  EXPECT_EQ(grid.CellOf({15, -3}), Cell(9, 0));
  EXPECT_EQ(grid.CellOf({4.5, -100}), Cell(4, 0));
  EXPECT_EQ(grid.CellOf({11, 7}), Cell(9, 3));
}

TEST(GridGeometryTest, HugeCoordinatesDoNotOverflow) {
  const GridGeometry grid(kBox, 10);
  const double max = std::numeric_limits<double>::max();
  EXPECT_EQ(grid.CellOf({1e308, 1e308}), Cell(9, 9));
  EXPECT_EQ(grid.CellOf({-1e308, -1e308}), Cell(0, 0));
  EXPECT_EQ(grid.CellOf({1e308, -1e308}), Cell(9, 0));
  EXPECT_EQ(grid.CellOf({-1e308, 1e308}), Cell(0, 9));
  EXPECT_EQ(grid.CellOf({max, -max}), Cell(9, 0));
  EXPECT_EQ(grid.CellOf({1e300, 3}), Cell(9, 1));
  for (double x : {1e308, -1e308, max, -max}) {
    EXPECT_GE(grid.GridX(x), 0);
    EXPECT_LT(grid.GridX(x), 10);
    EXPECT_GE(grid.Column(x), 0);
    EXPECT_LT(grid.Column(x), 10);
    EXPECT_LT(grid.Row(x), 10);
  }
}

TEST(GridGeometryTest, CellBoxesTileTheBox) {
  const GridGeometry grid(kBox, 10);
  const BoundingBox b = grid.CellBox(3, 4);
  EXPECT_DOUBLE_EQ(b.min_x, 3);
  EXPECT_DOUBLE_EQ(b.min_y, 8);
  EXPECT_DOUBLE_EQ(b.max_x, 4);
  EXPECT_DOUBLE_EQ(b.max_y, 10);
  const BoundingBox last = grid.CellBox(9, 9);
  EXPECT_DOUBLE_EQ(last.max_x, 10);
  EXPECT_DOUBLE_EQ(last.max_y, 20);

  // On an uneven box every cell's centre maps back to the cell.
  const GridGeometry odd(BoundingBox{-3.5, 100, 7.25, 180.5}, 13);
  for (int row = 0; row < 13; ++row) {
    for (int col = 0; col < 13; ++col) {
      const BoundingBox c = odd.CellBox(col, row);
      const Point2 centre{(c.min_x + c.max_x) / 2, (c.min_y + c.max_y) / 2};
      EXPECT_EQ(odd.CellOf(centre), size_t(row) * 13 + col);
    }
  }
}

TEST(GridGeometryTest, DegenerateBoxIsWidenedToOneUnit) {
  const GridGeometry point(BoundingBox{5, 5, 5, 5}, 4);
  EXPECT_EQ(point.box().min_x, 5);
  EXPECT_EQ(point.box().max_x, 6);
  EXPECT_EQ(point.box().max_y, 6);
  EXPECT_DOUBLE_EQ(point.cell_width(), 0.25);
  EXPECT_EQ(point.CellOf({5, 5}), 0u);
  EXPECT_EQ(point.CellOf({5.9, 5.9}), 15u);
  EXPECT_EQ(point.CellOf({5.3, 5.6}), 2u * 4 + 1);

  const GridGeometry flat(BoundingBox{0, 2, 8, 2}, 4);
  EXPECT_EQ(flat.box().max_x, 8);  // only the degenerate side grows
  EXPECT_EQ(flat.box().max_y, 3);
  EXPECT_EQ(flat.CellOf({7, 2}), 3u);
}

TEST(GridGeometryTest, SizeBelowOneBecomesOne) {
  const GridGeometry grid(kBox, 0);
  EXPECT_EQ(grid.size(), 1);
  EXPECT_EQ(grid.CellOf({3, 3}), 0u);
}

TEST(QueryHistogramTest, DrainReturnsExactCountsAndResets) {
  QueryHistogram h(GridGeometry(kBox, 10));
  for (int i = 0; i < 7; ++i) h.Add({0.5, 0.5});
  for (int i = 0; i < 3; ++i) h.Add({9.5, 19.5});
  h.Add({-1e308, 1e308});  // clamps into cell (0, 9)
  std::vector<double> counts;
  h.Drain(&counts);
  ASSERT_EQ(counts.size(), 100u);
  EXPECT_EQ(counts[Cell(0, 0)], 7);
  EXPECT_EQ(counts[Cell(9, 9)], 3);
  EXPECT_EQ(counts[Cell(0, 9)], 1);
  EXPECT_EQ(Sum(counts), 11);

  std::vector<double> again;
  h.Drain(&again);
  EXPECT_EQ(Sum(again), 0) << "Drain() must reset the counts";
}

TEST(QueryHistogramTest, DrainAddsIntoExistingCounts) {
  QueryHistogram h(GridGeometry(kBox, 10));
  h.Add({2.5, 4.5});
  std::vector<double> counts(100, 1.0);
  h.Drain(&counts);
  EXPECT_EQ(counts[Cell(2, 2)], 2);
  EXPECT_EQ(Sum(counts), 101);
  EXPECT_GE(h.MemoryBytes(), QueryHistogram::kShards * 100 * sizeof(uint32_t));
}

// Thread i counts kPerThread queries, spread over cells i, i + 4, ...
constexpr int kThreads = 4;
constexpr int kPerThread = 50000;

void AddFromThread(QueryHistogram* h, int thread) {
  for (int k = 0; k < kPerThread; ++k) {
    const int cell = (thread + 4 * (k % 25)) % 100;
    h->Add({cell % 10 + 0.5, 2.0 * (cell / 10) + 1});
  }
}

TEST(QueryHistogramTest, ConcurrentAddsAreAllCounted) {
  QueryHistogram h(GridGeometry(kBox, 10));
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back(AddFromThread, &h, i);
  }
  for (std::thread& t : threads) t.join();
  std::vector<double> counts;
  h.Drain(&counts);
  EXPECT_EQ(Sum(counts), double{kThreads} * kPerThread);
  for (int cell = 0; cell < 100; ++cell) {
    EXPECT_EQ(counts[cell], kPerThread / 25) << "cell " << cell;
  }
}

TEST(QueryHistogramTest, DrainConcurrentWithAddsLosesNothing) {
  QueryHistogram h(GridGeometry(kBox, 10));
  std::atomic<int> running{kThreads};
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back([&h, &running, i] {
      AddFromThread(&h, i);
      running.fetch_sub(1);
    });
  }
  std::vector<double> total;
  // Drains at least once even if a loaded machine runs every adder to the
  // end before this loop starts.
  do {
    h.Drain(&total);
  } while (running.load() > 0);
  for (std::thread& t : threads) t.join();
  h.Drain(&total);
  EXPECT_EQ(Sum(total), double{kThreads} * kPerThread);
}

}  // namespace
}  // namespace locator
