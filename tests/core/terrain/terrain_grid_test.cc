// TriangulateGrid: the certificate checked by brute force on the served
// TIN, the domain of valid cells (holes, borders, lone samples), the grid's
// own TIN at max_error 0, budgets, threads, determinism and bad input.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "common/elevation_grid.h"
#include "locator/dataset.h"
#include "locator/engine.h"
#include "server/core/terrain/fractal_terrain.h"
#include "server/core/terrain/grid/triangulate_grid.h"
#include "server/core/terrain/points/reference_greedy.h"
#include "tests/core/locator_checks.h"
#include "tests/core/terrain/terrain_test_support.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

using test::InGridDomain;
using test::MeasureServed;
using test::RoundingTolerance;
using test::ServedErrors;
using test::WithError;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

ElevationGrid Terrain(uint32_t width, uint32_t height, uint64_t seed = 7) {
  FractalTerrainOptions options;
  options.seed = seed;
  options.octaves = 6;
  options.base_frequency = 1.5;
  options.persistence = 0.55;
  options.height = 100;
  return FractalTerrain(width, height, options);
}

double Range(const ElevationGrid& grid) {
  float lo = std::numeric_limits<float>::infinity();
  float hi = -lo;
  for (const float v : grid.values) {
    if (std::isnan(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return hi - lo;
}

// Samples within `radius` of (cx, cy) become nodata.
void CutDisc(ElevationGrid* grid, double cx, double cy, double radius) {
  for (uint32_t row = 0; row < grid->height; ++row) {
    for (uint32_t col = 0; col < grid->width; ++col) {
      if (std::hypot(col - cx, row - cy) <= radius) {
        grid->values[grid->Index(col, row)] = kNaN;
      }
    }
  }
}

// Builds the TIN and checks its certificate against the engine's answers
// at every sample; returns the stats.
SimplificationStats BuildAndCertify(const ElevationGrid& grid,
                                    const TinOptions& options, Dataset* tin) {
  SimplificationStats stats;
  const Status s = TriangulateGrid(grid, options, tin, &stats);
  EXPECT_TRUE(s.ok()) << s.ToString();
  if (!s.ok()) return stats;
  const ServedErrors served = MeasureServed(grid, *tin);
  const double tolerance = RoundingTolerance(grid);
  EXPECT_NEAR(served.max_error, stats.max_error, tolerance);
  if (options.max_points == 0) {
    EXPECT_LE(stats.max_error, options.max_error);
    EXPECT_LE(served.max_error, options.max_error + tolerance);
  }
  EXPECT_EQ(served.in_domain, stats.source_samples - stats.unserved_samples);
  EXPECT_EQ(stats.vertices, tin->points.size());
  EXPECT_EQ(stats.triangles, tin->constraints.triangles.size());
  return stats;
}

TEST(TriangulateGridTest, CertificateIsTheServedErrorAtEverySample) {
  const ElevationGrid grid = Terrain(61, 47);
  for (const double fraction : {0.05, 0.01, 0.002}) {
    SCOPED_TRACE(fraction);
    Dataset tin;
    const SimplificationStats stats =
        BuildAndCertify(grid, WithError(fraction * Range(grid)), &tin);
    EXPECT_EQ(stats.source_samples, grid.samples());
    EXPECT_EQ(stats.unserved_samples, 0u);
    EXPECT_LT(stats.vertices, grid.samples());
    EXPECT_GT(stats.max_error, 0);
    EXPECT_EQ(tin.values.size(), tin.points.size());
  }
}

// Every combination of step signs: the output must stay counter-clockwise
// in dataset coordinates and the certificate hold.
TEST(TriangulateGridTest, EveryOrientationOfThePlacement) {
  for (const double sx : {1.0, -1.0}) {
    for (const double sy : {1.0, -1.0}) {
      SCOPED_TRACE(std::to_string(sx) + " " + std::to_string(sy));
      ElevationGrid grid = Terrain(33, 29);
      grid.origin_x = 500000.25;
      grid.origin_y = 4100000.5;
      grid.step_x = 30 * sx;
      grid.step_y = 30 * sy;
      Dataset tin;
      BuildAndCertify(grid, WithError(0.01 * Range(grid)), &tin);
    }
  }
}

TEST(TriangulateGridTest, NodataDiscInsideIsAHole) {
  ElevationGrid grid = Terrain(57, 51);
  CutDisc(&grid, 28, 25, 8.5);
  Dataset tin;
  const SimplificationStats stats =
      BuildAndCertify(grid, WithError(0.01 * Range(grid)), &tin);
  EXPECT_LT(stats.source_samples, grid.samples());
  StatusOr<std::unique_ptr<Engine>> created =
      Engine::Create(tin, EngineOptions());
  ASSERT_TRUE(created.ok()) << created.status().ToString();
  const std::unique_ptr<Engine> engine = *std::move(created);
  EXPECT_EQ(engine->dataset_info().holes, 1u);
  // The disc's centre and points between nodata samples: no value.
  for (const Point2 q :
       {grid.SampleAt(28, 25), Point2{28.5, -25.5}, Point2{22.25, -24.75}}) {
    LocateResult r;
    ASSERT_TRUE(engine->Locate(q, &r).ok());
    EXPECT_EQ(r.type, LocationType::kOutsideDomain) << q.x << " " << q.y;
    EXPECT_FALSE(r.has_value);
  }
}

TEST(TriangulateGridTest, NodataAlongTheBordersIsOutside) {
  ElevationGrid grid = Terrain(45, 40);
  for (uint32_t row = 0; row < grid.height; ++row) {
    for (uint32_t col = 0; col < grid.width; ++col) {
      // A ragged left band, a notch in the top border, a corner.
      const bool band = col < 3 + (row % 7 == 0 ? 2 : 0);
      const bool notch = row < 4 && col > 20 && col < 26;
      const bool corner = col + row > 75;
      if (band || notch || corner) grid.values[grid.Index(col, row)] = kNaN;
    }
  }
  Dataset tin;
  BuildAndCertify(grid, WithError(0.01 * Range(grid)), &tin);
}

TEST(TriangulateGridTest, LoneValidSamplesAreUnserved) {
  ElevationGrid grid = Terrain(20, 20);
  for (uint32_t row = 0; row < 20; ++row) {
    for (uint32_t col = 10; col < 20; ++col) {
      // A lone sample and a one-wide line in a nodata half.
      const bool keep = (col == 15 && row == 5) || (col == 17 && row > 8);
      if (!keep) grid.values[grid.Index(col, row)] = kNaN;
    }
  }
  Dataset tin;
  const SimplificationStats stats =
      BuildAndCertify(grid, WithError(0.01 * Range(grid)), &tin);
  EXPECT_EQ(stats.unserved_samples, 1u + 11u);
}

TEST(TriangulateGridTest, AllNodataIsRefused) {
  ElevationGrid grid = Terrain(10, 10);
  std::fill(grid.values.begin(), grid.values.end(), kNaN);
  Dataset tin;
  SimplificationStats stats;
  Status s = TriangulateGrid(grid, WithError(1), &tin, &stats);
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(s.message().find("0 of 100 samples are valid"), std::string::npos)
      << s.message();
  // Valid samples, but no two-by-two block of them.
  for (uint32_t i = 0; i < 100; i += 2) grid.values[i] = 1;
  s = TriangulateGrid(grid, WithError(1), &tin, &stats);
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(s.message().find("no cell of the grid has four valid corners"),
            std::string::npos)
      << s.message();
}

TEST(TriangulateGridTest, ZeroErrorKeepsEverySampleInTwoTrianglesPerCell) {
  ElevationGrid grid = Terrain(17, 13);
  CutDisc(&grid, 8, 6, 2.5);
  uint64_t valid_cells = 0;
  for (uint32_t row = 0; row + 1 < grid.height; ++row) {
    for (uint32_t col = 0; col + 1 < grid.width; ++col) {
      valid_cells += grid.IsValid(col, row) && grid.IsValid(col + 1, row) &&
                     grid.IsValid(col, row + 1) &&
                     grid.IsValid(col + 1, row + 1);
    }
  }
  Dataset tin;
  const SimplificationStats stats = BuildAndCertify(grid, WithError(0), &tin);
  EXPECT_EQ(stats.triangles, 2 * valid_cells);
  EXPECT_EQ(stats.vertices, stats.source_samples - stats.unserved_samples);
  EXPECT_EQ(stats.max_error, 0);
  StatusOr<std::unique_ptr<Engine>> created =
      Engine::Create(tin, EngineOptions());
  ASSERT_TRUE(created.ok()) << created.status().ToString();
  const std::unique_ptr<Engine> engine = *std::move(created);
  for (uint32_t row = 0; row < grid.height; ++row) {
    for (uint32_t col = 0; col < grid.width; ++col) {
      if (!InGridDomain(grid, col, row)) continue;
      LocateResult r;
      ASSERT_TRUE(engine->Locate(grid.SampleAt(col, row), &r).ok());
      EXPECT_EQ(r.type, LocationType::kVertex);
      EXPECT_EQ(r.value, grid.ValueAt(col, row));  // exactly
    }
  }
}

TEST(TriangulateGridTest, MaxPointsIsABudget) {
  const ElevationGrid grid = Terrain(40, 40);
  for (const uint64_t budget : {4u, 5u, 50u, 300u}) {
    SCOPED_TRACE(budget);
    TinOptions options = WithError(0);  // only the budget stops it
    options.max_points = budget;
    Dataset tin;
    const SimplificationStats stats = BuildAndCertify(grid, options, &tin);
    EXPECT_EQ(stats.vertices, budget);
    EXPECT_GT(stats.max_error, 0);
    EXPECT_EQ(stats.max_points, budget);
  }
  // Whichever limit comes first: a loose error stops before the budget.
  TinOptions options = WithError(0.05 * Range(grid));
  options.max_points = 1000;
  Dataset tin;
  const SimplificationStats stats = BuildAndCertify(grid, options, &tin);
  EXPECT_LT(stats.vertices, 1000u);
  EXPECT_LE(stats.max_error, options.max_error);
}

TEST(TriangulateGridTest, MaxPointsBelowTheBoundaryIsRefused) {
  ElevationGrid grid = Terrain(40, 40);
  CutDisc(&grid, 20, 20, 6);  // a hole with many corners
  TinOptions options = WithError(0.01 * Range(grid));
  options.max_points = 8;
  Dataset tin;
  SimplificationStats stats;
  const Status s = TriangulateGrid(grid, options, &tin, &stats);
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(s.message().find("max_points is 8"), std::string::npos)
      << s.message();
}

// Two threads cut the grid into tiles; both results are within the error,
// and both need about the vertices of straightforward greedy insertion.
TEST(TriangulateGridTest, OneAndTwoThreadsBothCertified) {
  ElevationGrid grid = Terrain(300, 270, 11);
  CutDisc(&grid, 150, 135, 20);  // a hole on the cut lines' crossing
  CutDisc(&grid, 40, 200, 9);
  const double e = 0.003 * Range(grid);
  Dataset one, two;
  const SimplificationStats s1 = BuildAndCertify(grid, WithError(e, 1), &one);
  const SimplificationStats s2 = BuildAndCertify(grid, WithError(e, 2), &two);
  ReferenceTin reference;
  ASSERT_TRUE(ReferenceGreedyGrid(grid, e, 0, &reference).ok());
  EXPECT_LE(reference.max_error, e);
  EXPECT_NEAR(static_cast<double>(s1.vertices), reference.vertices,
              0.05 * reference.vertices);
  EXPECT_NEAR(static_cast<double>(s2.vertices), reference.vertices,
              0.05 * reference.vertices);
}

TEST(TriangulateGridTest, SameInputSameOutput) {
  ElevationGrid grid = Terrain(280, 260, 3);
  CutDisc(&grid, 100, 100, 12);
  for (const unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(threads);
    const TinOptions options = WithError(0.004 * Range(grid), threads);
    Dataset a, b;
    SimplificationStats sa, sb;
    ASSERT_TRUE(TriangulateGrid(grid, options, &a, &sa).ok());
    ASSERT_TRUE(TriangulateGrid(grid, options, &b, &sb).ok());
    ASSERT_EQ(a.points.size(), b.points.size());
    for (size_t i = 0; i < a.points.size(); ++i) {
      ASSERT_EQ(a.points[i].x, b.points[i].x);
      ASSERT_EQ(a.points[i].y, b.points[i].y);
    }
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(a.constraints.triangles, b.constraints.triangles);
    EXPECT_EQ(sa.max_error, sb.max_error);
  }
}

TEST(TriangulateGridTest, ProgressIsReported) {
  const ElevationGrid grid = Terrain(120, 100);
  std::vector<TinProgress> reports;
  TinOptions options = WithError(0.001 * Range(grid));
  options.progress_interval_s = 1e-9;  // every update is due
  options.progress = [&](const TinProgress& p) { reports.push_back(p); };
  Dataset tin;
  SimplificationStats stats;
  ASSERT_TRUE(TriangulateGrid(grid, options, &tin, &stats).ok());
  ASSERT_GE(reports.size(), 2u);
  for (size_t i = 1; i < reports.size(); ++i) {
    EXPECT_GE(reports[i].vertices, reports[i - 1].vertices);
    EXPECT_GE(reports[i].seconds, reports[i - 1].seconds);
  }
  EXPECT_EQ(reports.back().vertices, stats.vertices);
  EXPECT_GT(reports.front().max_error, options.max_error);
}

// The served TIN answers like CGAL's own locate on the same triangulation.
TEST(TriangulateGridTest, ServedDemAgreesWithCgal) {
  ElevationGrid grid = Terrain(90, 70);
  CutDisc(&grid, 45, 35, 7);
  Dataset tin;
  SimplificationStats stats;
  ASSERT_TRUE(
      TriangulateGrid(grid, WithError(0.005 * Range(grid)), &tin, &stats).ok());
  std::unique_ptr<Triangulation> t = test::BuildTriangulation(tin);
  ASSERT_NE(t, nullptr);
  std::vector<Point2> queries =
      test::UniformQueries(t->bounding_box().Inflated(0.05), 4000, 5);
  for (uint32_t row = 0; row < grid.height; row += 3) {
    for (uint32_t col = 0; col < grid.width; col += 3) {
      queries.push_back(grid.SampleAt(col, row));
    }
  }
  for (const std::string_view strategy : {"walk", "self-tuning"}) {
    SCOPED_TRACE(strategy);
    std::unique_ptr<PointLocator> locator = test::MakeLocator(strategy, *t);
    ASSERT_NE(locator, nullptr);
    test::ExpectAllAgree(*locator, *t, queries);
  }
}

TEST(TriangulateGridTest, BadInputIsRefused) {
  const auto refused = [](const ElevationGrid& grid, const TinOptions& options,
                          const std::string& needle) {
    Dataset tin;
    SimplificationStats stats;
    const Status s = TriangulateGrid(grid, options, &tin, &stats);
    EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << needle;
    EXPECT_NE(s.message().find(needle), std::string::npos) << s.message();
  };
  const ElevationGrid good = Terrain(8, 8);
  refused(good, WithError(-1), "max_error is -1");
  refused(good, WithError(std::nan("")), "max_error is nan");
  refused(good, WithError(INFINITY), "max_error is inf");
  ElevationGrid grid = good;
  grid.values[9] = INFINITY;
  refused(grid, WithError(1), "sample (col 1, row 1) is infinite");
  grid = good;
  grid.values.pop_back();
  refused(grid, WithError(1), "63 values for 8 x 8 samples");
  grid = good;
  grid.width = 1;
  grid.height = 64;
  refused(grid, WithError(1), "at least 2 x 2");
  grid = good;
  grid.step_x = 0;
  refused(grid, WithError(1), "non-zero steps");
  grid = good;
  grid.origin_y = NAN;
  refused(grid, WithError(1), "must be finite");
  grid = good;
  grid.step_x = 1e308;
  refused(grid, WithError(1), "keep every sample finite");
  grid = good;
  grid.origin_x = 1e17;  // a step of 1 is lost in rounding
  refused(grid, WithError(0), "rounds a triangle flat");
}

}  // namespace
}  // namespace locator
