// The parts of the tiled build (server/core/tiling/): the cell grid, the
// hull, the circumdisk bound and the halo's region tests.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "common/hilbert.h"
#include "locator/dataset_sources.h"
#include "server/core/cgal/orientation.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/tiling/cells/cell_grid.h"
#include "server/core/tiling/cells/circumdisk.h"
#include "server/core/tiling/cells/halo_cells.h"
#include "server/core/tiling/cells/sorted_points.h"
#include "server/core/tiling/hull_edges.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

// The classic walk (Wikipedia's xy2d, as hilbert.h computed it before its
// table): the table-driven HilbertIndex must give the same positions, or
// every mesh's order would change.
uint32_t ClassicHilbertIndex(uint32_t x, uint32_t y) {
  uint32_t d = 0;
  for (uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const uint32_t rx = (x & s) ? 1 : 0;
    const uint32_t ry = (y & s) ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = 0xffff - x;
        y = 0xffff - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

TEST(HilbertTest, TableWalkIsTheClassicWalk) {
  for (uint32_t x = 0; x < 65536; x += 61) {
    for (uint32_t y = 0; y < 65536; y += 59) {
      ASSERT_EQ(HilbertIndex(x, y), ClassicHilbertIndex(x, y)) << x << " " << y;
    }
  }
  std::mt19937 rng(6);
  for (int k = 0; k < 200000; ++k) {
    const uint32_t x = rng() & 0xffff, y = rng() & 0xffff;
    ASSERT_EQ(HilbertIndex(x, y), ClassicHilbertIndex(x, y)) << x << " " << y;
  }
  for (const uint32_t x : {0u, 1u, 0x7fffu, 0x8000u, 0xfffeu, 0xffffu}) {
    for (const uint32_t y : {0u, 1u, 0x7fffu, 0x8000u, 0xfffeu, 0xffffu}) {
      ASSERT_EQ(HilbertIndex(x, y), ClassicHilbertIndex(x, y)) << x << " " << y;
    }
  }
}

TEST(CellGridTest, CellNumbersFollowTheHilbertKeyAndInvert) {
  const BoundingBox box{-3, 2, 5, 2.5};
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> ux(box.min_x, box.max_x);
  std::uniform_real_distribution<double> uy(box.min_y, box.max_y);
  for (int level = 0; level <= CellGrid::kMaxLevel; ++level) {
    const CellGrid grid(box, level);
    for (int k = 0; k < 2000; ++k) {
      const Point2 p{ux(rng), uy(rng)};
      ASSERT_EQ(grid.FineKey(p), HilbertKey(p, box));
      const uint32_t cell = grid.CellOfKey(grid.FineKey(p));
      ASSERT_EQ(cell, grid.Cell(grid.Column(p.x), grid.Row(p.y)));
      uint32_t column, row;
      grid.CellPosition(cell, &column, &row);
      ASSERT_EQ(column, grid.Column(p.x));
      ASSERT_EQ(row, grid.Row(p.y));
      const CellGrid::Interval span = grid.RowSpan(row);
      ASSERT_LE(span.lo, p.y);
      ASSERT_GE(span.hi, p.y);
    }
  }
  const CellGrid grid(box, 4);
  std::set<uint32_t> cells;
  for (uint32_t column = 0; column < grid.side(); ++column) {
    for (uint32_t row = 0; row < grid.side(); ++row) {
      cells.insert(grid.Cell(column, row));
    }
  }
  EXPECT_EQ(cells.size(), grid.num_cells());
  EXPECT_EQ(*cells.rbegin(), grid.num_cells() - 1);
}

// Rows hold exactly the points Row() puts there, also at the cells' own
// edges and when the box's extent overflows a double.
TEST(CellGridTest, RowSpansHoldTheirPointsAtEdgesAndExtremes) {
  for (const BoundingBox& box :
       {BoundingBox{0, 0, 1, 1}, BoundingBox{-1e308, -1e308, 1e308, 1e308},
        BoundingBox{1e6, 1e6, 1e6 + 1e-3, 1e6 + 1e-3},
        BoundingBox{0, 1e-310, 1, 3e-310}}) {
    const CellGrid grid(box, 7);
    for (uint32_t row = 0; row < grid.side(); ++row) {
      const CellGrid::Interval span = grid.RowSpan(row);
      ASSERT_LE(span.lo, span.hi);
      // The band's exact edges and their neighbouring doubles.
      const double f = double(row) / grid.side();
      const double edge = box.min_y * (1 - f) + box.max_y * f;
      for (double y :
           {edge, std::nextafter(edge, -1e308), std::nextafter(edge, 1e308)}) {
        y = std::clamp(y, box.min_y, box.max_y);
        const uint32_t r = grid.Row(y);
        const CellGrid::Interval s = grid.RowSpan(r);
        ASSERT_TRUE(s.lo <= y && y <= s.hi) << "row " << row << " y " << y;
      }
    }
    for (int k = 0; k + 1 < 100; ++k) {
      const double a = box.min_y + (box.max_y - box.min_y) * k / 100;
      const double b = box.min_y + (box.max_y - box.min_y) * (k + 1) / 100;
      if (std::isfinite(a) && std::isfinite(b)) {
        ASSERT_LE(grid.Row(a), grid.Row(b));  // monotone
      }
    }
  }
}

// The hull with every collinear point on it: the edges CGAL's
// triangulation has on its hull.
TEST(HullEdgesTest, AreTheTriangulationsHullEdges) {
  for (const Dataset& dataset :
       {GenerateUniform(5000, 2), test::GridDataset(50),
        test::LinesDataset(3000, 3), test::CocircularDataset(),
        GenerateClusters(5000, 4, 9)}) {
    auto t = test::BuildTriangulation(dataset);
    ASSERT_NE(t, nullptr);
    SortedPoints sorted;
    SortPoints(dataset.points, 4, 2, &sorted);
    const HullEdges hull = HullEdges::Compute(sorted.points, 2);
    std::set<std::pair<uint32_t, uint32_t>> expected;
    for (const uint32_t edge : t->mesh().hull()) {
      const uint32_t f = ServingMesh::EdgeFace(edge);
      const int i = ServingMesh::EdgeIndex(edge);
      expected.insert(
          std::minmax(t->mesh().PublicId(t->mesh().Corner(f, Ccw(i))),
                      t->mesh().PublicId(t->mesh().Corner(f, Cw(i)))));
    }
    std::set<std::pair<uint32_t, uint32_t>> got;
    const std::vector<uint32_t>& ring = hull.ring();
    for (size_t k = 0; k < ring.size(); ++k) {
      const uint32_t a = ring[k], b = ring[(k + 1) % ring.size()];
      EXPECT_TRUE(hull.Contains(a, b));
      EXPECT_TRUE(hull.Contains(b, a));
      got.insert(std::minmax(sorted.ids[a], sorted.ids[b]));
    }
    EXPECT_EQ(got, expected) << dataset.source;
    EXPECT_FALSE(hull.Contains(ring[0], ring[2]));
  }
}

// The bound contains the exact circumcircle: |C* - C| + r* <= R, checked
// with the exact circumcentre and interval square roots, all scaled by a
// power of two (exactly) so that squares stay in range.
void ExpectContainsCircumcircle(const Point2& a, const Point2& b,
                                const Point2& c) {
  using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
  Disk disk;
  if (!CircumdiskBound(a, b, c, &disk)) return;  // no bound claimed
  int exponent = 0;
  std::frexp(
      std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y),
                std::abs(c.x), std::abs(c.y), std::abs(disk.center.x),
                std::abs(disk.center.y), disk.radius}),
      &exponent);
  const auto scaled = [&](const Point2& p) {
    return Exact::Point_2(
        Exact::FT(p.x) / Exact::FT(std::ldexp(1.0, exponent)),
        Exact::FT(p.y) / Exact::FT(std::ldexp(1.0, exponent)));
  };
  const Exact::Point_2 ea = scaled(a), eb = scaled(b), ec = scaled(c);
  const Exact::Point_2 center = CGAL::circumcenter(ea, eb, ec);
  const Exact::Point_2 computed = scaled(disk.center);
  disk.radius = std::ldexp(disk.radius, -exponent);
  const auto offset =
      CGAL::to_interval(CGAL::squared_distance(center, computed));
  const auto radius = CGAL::to_interval(CGAL::squared_distance(center, ea));
  const double reach = std::sqrt(offset.second) * (1 + 1e-15) +
                       std::sqrt(radius.second) * (1 + 1e-15);
  EXPECT_LE(reach, disk.radius) << a.x << "," << a.y << " " << b.x << "," << b.y
                                << " " << c.x << "," << c.y;
}

TEST(CircumdiskTest, BoundContainsTheExactCircle) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 3000; ++k) {
    const double scale = std::ldexp(1.0, static_cast<int>(k % 40) * 50 - 1000);
    const Point2 origin{1e6 * u(rng), -3e5 * u(rng)};
    Point2 p[3];
    for (Point2& q : p) {
      q = {origin.x + scale * u(rng), origin.y + scale * u(rng)};
    }
    if (k % 3 == 0) {
      // Nearly collinear: the third point a hair off the first two's line.
      p[2] = {(p[0].x + p[1].x) / 2, (p[0].y + p[1].y) / 2 + scale * 1e-9};
    }
    const double turn = (p[1].x - p[0].x) * (p[2].y - p[0].y) -
                        (p[1].y - p[0].y) * (p[2].x - p[0].x);
    if (turn < 0) std::swap(p[1], p[2]);
    ExpectContainsCircumcircle(p[0], p[1], p[2]);
  }
  Disk disk;
  EXPECT_FALSE(CircumdiskBound({0, 0}, {1, 1}, {2, 2}, &disk));
  EXPECT_FALSE(CircumdiskBound({-1e308, 0}, {1e308, 0}, {0, 1e308}, &disk));
  ASSERT_TRUE(CircumdiskBound({0, 0}, {2, 0}, {0, 2}, &disk));
  EXPECT_NEAR(disk.center.x, 1, 1e-15);
  EXPECT_NEAR(disk.radius, std::sqrt(2), 1e-13);
}

// Every point of a disk or half-plane lies in a cell the test reports
// (wanted), when every cell has points and the window is the grid; at
// scales where squares of lengths underflow or overflow too.
class HaloCellsTest : public ::testing::TestWithParam<double> {};

TEST_P(HaloCellsTest, RegionsMissNoCell) {
  const double scale = GetParam();
  std::vector<Point2> points;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      points.push_back({(x + 0.5) / 64 * scale, (y + 0.5) / 64 * scale});
    }
  }
  SortedPoints sorted;
  SortPoints(points, 1, 1, &sorted);
  ASSERT_EQ(sorted.grid.level(), 6);
  const BoundingBox& box = sorted.grid.box();
  const SortedPointsSource source(sorted);
  HaloCells halo(sorted.grid, source);
  const uint32_t last = sorted.grid.side() - 1;
  const auto wanted_set = [&] {
    std::vector<uint32_t> cells = halo.TakeWanted();
    return std::set<uint32_t>(cells.begin(), cells.end());
  };
  const auto cell_of = [&](const Point2& p) {
    return sorted.grid.Cell(sorted.grid.Column(p.x), sorted.grid.Row(p.y));
  };
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 300; ++k) {
    halo.Clear();
    halo.SetWindow({0, 0, last, last});
    const Disk disk{
        {(u(rng) * 1.4 - 0.2) * scale, (u(rng) * 1.4 - 0.2) * scale},
        u(rng) * u(rng) * 0.6 * scale};
    const HaloCells::Cover cover = halo.CoverDisk(disk);
    EXPECT_FALSE(cover.beyond);
    const std::set<uint32_t> wanted = wanted_set();
    EXPECT_EQ(cover.covered, wanted.empty());
    for (int s = 0; s < 400; ++s) {
      const double angle = 2 * M_PI * s / 400;
      for (const double f : {1.0, 0.999, 0.5}) {
        const Point2 p{disk.center.x + f * disk.radius * std::cos(angle),
                       disk.center.y + f * disk.radius * std::sin(angle)};
        if (!box.Contains(p)) continue;
        ASSERT_TRUE(wanted.count(cell_of(p))) << k << " " << s;
      }
    }
    halo.Clear();
    halo.SetWindow({0, 0, last, last});
    const Point2 a{u(rng) * scale, u(rng) * scale};
    const Point2 b{u(rng) * scale, u(rng) * scale};
    (void)halo.CoverRightOf(a, b);
    const std::set<uint32_t> right = wanted_set();
    for (int s = 0; s < 2000; ++s) {
      const Point2 p{box.min_x + u(rng) * box.width(),
                     box.min_y + u(rng) * box.height()};
      if (Orientation(a, b, p) != Side::kLeft) {
        ASSERT_TRUE(right.count(cell_of(p))) << k << " " << s;
      }
    }
  }
  // A window smaller than the region: beyond, and only cells inside it.
  halo.Clear();
  halo.SetWindow({10, 10, 20, 20});
  const HaloCells::Cover cover =
      halo.CoverDisk({{0.25 * scale, 0.25 * scale}, 0.3 * scale});
  EXPECT_TRUE(cover.beyond);
  EXPECT_FALSE(cover.covered);
  EXPECT_EQ(wanted_set().size(), 11u * 11u);
  EXPECT_TRUE(halo.CoverWindow().beyond);
}

INSTANTIATE_TEST_SUITE_P(Scales, HaloCellsTest,
                         ::testing::Values(1.0, 1e-305, 1e300));

}  // namespace
}  // namespace locator
