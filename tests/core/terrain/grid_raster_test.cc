// ForEachRun: the runs of samples a grid triangle covers are exactly the
// samples its edge functions put inside (on an open edge: outside), with or
// without its corners, checked against a test of every sample of its box.

#include "server/core/terrain/grid/grid_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>

namespace locator {
namespace {

TEST(GridRasterTest, RunsAreExactlyTheSamplesInside) {
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int64_t> coordinate(0, 40);
  int triangles = 0;
  while (triangles < 3000) {
    std::array<GridPoint, 3> c;
    for (GridPoint& p : c) p = {coordinate(rng), coordinate(rng)};
    const int64_t area = EdgeFunction(c[0], c[1]).At(c[2].x, c[2].y);
    if (area == 0) continue;
    if (area < 0) std::swap(c[1], c[2]);  // counter-clockwise
    ++triangles;
    const std::array<bool, 3> open = {rng() % 3 == 0, rng() % 3 == 0,
                                      rng() % 3 == 0};
    const bool skip_corners = rng() % 2 == 0;
    std::set<std::pair<int64_t, int64_t>> runs, expected;
    ForEachRun(c, open, skip_corners,
               [&](int64_t y, int64_t first, int64_t last) {
                 ASSERT_LE(first, last);
                 for (int64_t x = first; x <= last; ++x) {
                   ASSERT_TRUE(runs.insert({x, y}).second);
                 }
               });
    for (int64_t y = 0; y <= 40; ++y) {
      for (int64_t x = 0; x <= 40; ++x) {
        bool inside = true;
        for (int i = 0; i < 3; ++i) {
          const int64_t w = EdgeFunction(c[i], c[(i + 1) % 3]).At(x, y);
          inside &= open[i] ? w > 0 : w >= 0;
        }
        const bool corner =
            std::find(c.begin(), c.end(), GridPoint{x, y}) != c.end();
        if (inside && !(skip_corners && corner)) expected.insert({x, y});
      }
    }
    ASSERT_EQ(runs, expected)
        << "triangle (" << c[0].x << "," << c[0].y << ") (" << c[1].x << ","
        << c[1].y << ") (" << c[2].x << "," << c[2].y << ")";
  }
}

}  // namespace
}  // namespace locator
