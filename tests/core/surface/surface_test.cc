// The engine's surface queries besides profiles: rasters rendered with
// scanline coherence agree cell by cell with CGAL's own locate() (value,
// nodata outside the hull and in holes, centres exactly on vertices and
// edges), and the interpolations Locate and LocateBatch offer.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "locator/engine.h"
#include "server/core/cgal/triangulation.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

constexpr double kNodata = -9999;

// A constraint through `points` with the values of test::Plane there.
Polyline OnThePlane(std::vector<Point2> points) {
  Polyline line{std::move(points), {}};
  for (const Point2& p : line.points) line.values.push_back(test::Plane(p));
  return line;
}

std::unique_ptr<Engine> EngineFor(Dataset dataset,
                                  const std::string& strategy = "self-tuning") {
  EngineOptions options;
  options.strategy = strategy;
  StatusOr<std::unique_ptr<Engine>> engine =
      Engine::Create(std::move(dataset), options);
  EXPECT_TRUE(engine.ok()) << engine.status().ToString();
  return engine.ok() ? *std::move(engine) : nullptr;
}

std::vector<double> Render(const Engine& engine, const RasterSpec& spec) {
  std::vector<double> cells(spec.cells());
  const Status s = engine.RenderRows(spec, 0, spec.height, cells.data());
  EXPECT_TRUE(s.ok()) << s.ToString();
  return cells;
}

// Checks every cell of `spec` rendered by `engine` against CGAL's locate()
// on the same dataset: nodata exactly where the reference has no value,
// the reference's linear value (within `tolerance`) elsewhere.
void ExpectCellsMatchReference(const Engine& engine, const Dataset& dataset,
                               const RasterSpec& spec, double tolerance) {
  const std::unique_ptr<Triangulation> t = test::BuildTriangulation(dataset);
  ASSERT_NE(t, nullptr);
  const std::vector<double> cells = Render(engine, spec);
  int mismatches = 0;
  for (uint32_t row = 0; row < spec.height; ++row) {
    for (uint32_t col = 0; col < spec.width; ++col) {
      const Point2 q = spec.CellCentre(col, row);
      const LocateResult want = t->ReferenceLocate(q);
      const double got = cells[size_t{row} * spec.width + col];
      if (!want.has_value) {
        if (got != kNodata && ++mismatches < 10) {
          ADD_FAILURE() << "cell (" << col << ", " << row << ") at (" << q.x
                        << ", " << q.y << ") is " << LocationTypeName(want.type)
                        << " but holds " << got;
        }
      } else if (!(std::abs(got - want.value) <= tolerance) &&
                 ++mismatches < 10) {
        ADD_FAILURE() << "cell (" << col << ", " << row << ") at (" << q.x
                      << ", " << q.y << "): " << got << " vs CGAL's "
                      << want.value;
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(RasterTest, CellsAgreeWithCgalInsideAndNodataOutsideTheHull) {
  const Dataset dataset = test::PlaneDataset(3000, 5);
  const auto engine = EngineFor(dataset);
  ASSERT_NE(engine, nullptr);
  const RasterSpec spec{.box = BoundingBox{-0.1, -0.05, 1.1, 1.02},
                        .width = 157,
                        .height = 131,
                        .nodata = kNodata};
  ExpectCellsMatchReference(*engine, dataset, spec, 1e-12);
  // The plane is reproduced exactly by linear interpolation.
  const std::vector<double> cells = Render(*engine, spec);
  for (uint32_t row = 0; row < spec.height; ++row) {
    for (uint32_t col = 0; col < spec.width; ++col) {
      const double v = cells[size_t{row} * spec.width + col];
      if (v != kNodata) {
        EXPECT_NEAR(v, test::Plane(spec.CellCentre(col, row)), 1e-12);
      }
    }
  }
}

TEST(RasterTest, CentresOnVerticesAndEdgesOfAnIntegerGrid) {
  // Cell centres fall exactly on the grid's vertices and on the middle of
  // its edges (co-circular squares: the diagonal CGAL chose is one of two).
  Dataset dataset = test::GridDataset(12);
  for (const Point2& p : dataset.points) dataset.values.push_back(p.x * p.y);
  const auto engine = EngineFor(dataset);
  ASSERT_NE(engine, nullptr);
  const RasterSpec spec{.box = BoundingBox{-0.25, -0.25, 11.25, 11.25},
                        .width = 23,
                        .height = 23,
                        .nodata = kNodata};
  ExpectCellsMatchReference(*engine, dataset, spec, 1e-12);
}

TEST(RasterTest, HolesAndTheOutsideOfTheBoundaryAreNodata) {
  Dataset dataset = test::PlaneDataset(4000, 11);
  dataset.constraints.rings.push_back(
      OnThePlane({{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}}));
  dataset.constraints.rings.push_back(
      OnThePlane({{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}));
  const auto engine = EngineFor(dataset);
  ASSERT_NE(engine, nullptr);
  // Columns at x = 0.1, 0.4, 0.6 and 0.9 run along the rings.
  const RasterSpec spec{.box = BoundingBox{0.0, 0.0, 1.0, 1.0},
                        .width = 100,
                        .height = 80,
                        .nodata = kNodata};
  ExpectCellsMatchReference(*engine, dataset, spec, 1e-12);
  const std::vector<double> cells = Render(*engine, spec);
  EXPECT_EQ(cells[40 * 100 + 50], kNodata);  // (0.505, 0.49375): the hole
  EXPECT_NE(cells[40 * 100 + 30], kNodata);  // (0.305, 0.49375): inside
}

TEST(RasterTest, RowsRenderedInPiecesEqualTheWhole) {
  const auto engine = EngineFor(test::PlaneDataset(2000, 3), "jump-and-walk");
  ASSERT_NE(engine, nullptr);
  const RasterSpec spec{.box = BoundingBox{0, 0, 1, 1},
                        .width = 64,
                        .height = 48,
                        .nodata = kNodata};
  const std::vector<double> whole = Render(*engine, spec);
  std::vector<double> pieces(spec.cells());
  for (uint32_t first = 0; first < spec.height; first += 7) {
    const uint32_t rows = std::min<uint32_t>(7, spec.height - first);
    ASSERT_TRUE(engine
                    ->RenderRows(spec, first, rows,
                                 pieces.data() + size_t{first} * spec.width)
                    .ok());
  }
  EXPECT_EQ(whole, pieces);
}

// RenderPoints over a raster's cell centres (a box wider than the data, so
// rows start outside the hull too) renders what RenderRows does; a point
// that is not finite gets nodata, and rows of no points are refused.
TEST(RasterTest, PointsInRowsRenderAsTheRaster) {
  const auto engine = EngineFor(test::PlaneDataset(2000, 3), "jump-and-walk");
  ASSERT_NE(engine, nullptr);
  const RasterSpec spec{.box = BoundingBox{-0.2, -0.1, 1.1, 1.2},
                        .width = 64,
                        .height = 48,
                        .nodata = kNodata};
  std::vector<Point2> centres;
  for (uint32_t row = 0; row < spec.height; ++row) {
    for (uint32_t col = 0; col < spec.width; ++col) {
      centres.push_back(spec.CellCentre(col, row));
    }
  }
  centres[70] = Point2{NAN, 0.5};
  std::vector<double> points(centres.size());
  ASSERT_TRUE(engine
                  ->RenderPoints(centres, spec.width, Interpolation::kLinear,
                                 kNodata, points.data())
                  .ok());
  const std::vector<double> cells = Render(*engine, spec);
  for (size_t i = 0; i < cells.size(); ++i) {
    if (i == 70) continue;
    ASSERT_NEAR(points[i], cells[i], 1e-12) << "cell " << i;
  }
  EXPECT_EQ(points[70], kNodata);
  const Status no_rows = engine->RenderPoints(
      centres, 0, Interpolation::kLinear, kNodata, points.data());
  EXPECT_EQ(no_rows.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(no_rows.message().find("row_length"), std::string::npos);
}

// A scan places most points in the face it already holds, with no walk:
// the value there is still a locate's, bit for bit (on a rough surface,
// where any other rounding would show), and so is nodata outside.
TEST(RasterTest, ScannedValuesAreLocateValuesBitForBit) {
  Dataset rough = test::PlaneDataset(3000, 4);
  std::mt19937_64 random(8);
  std::uniform_real_distribution<double> height(-1e3, 1e3);
  for (double& v : rough.values) v = height(random);
  const auto engine = EngineFor(std::move(rough));
  ASSERT_NE(engine, nullptr);
  // Rows of 300 points, 20 to a triangle's width, from outside the hull
  // across it, slightly slanted as a tile's rows are in a dataset's CRS.
  std::vector<Point2> points;
  for (int row = 0; row < 40; ++row) {
    for (int col = 0; col < 300; ++col) {
      points.push_back({-0.1 + 1.2 * col / 299.0 + 1e-3 * row,
                        1.05 - row / 39.0 * 1.1 + 2e-4 * col});
    }
  }
  std::vector<double> scanned(points.size());
  ASSERT_TRUE(engine
                  ->RenderPoints(points, 300, Interpolation::kLinear, kNodata,
                                 scanned.data())
                  .ok());
  std::vector<LocateResult> located;
  ASSERT_TRUE(engine->LocateBatch(points, &located).ok());
  int inside = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (located[i].type != LocationType::kFace) {
      if (located[i].type == LocationType::kOutsideConvexHull) {
        ASSERT_EQ(scanned[i], kNodata) << "point " << i;
      }
      continue;
    }
    ++inside;
    ASSERT_EQ(scanned[i], located[i].value) << "point " << i;
  }
  EXPECT_GT(inside, 8000);
}

TEST(RasterTest, BadSpecsAreInvalidArgument) {
  const auto engine = EngineFor(test::PlaneDataset(500, 3));
  ASSERT_NE(engine, nullptr);
  std::vector<double> out(100);
  const BoundingBox box{0, 0, 1, 1};
  const auto error = [&](const RasterSpec& spec, uint32_t first,
                         uint32_t rows) {
    const Status s = engine->RenderRows(spec, first, rows, out.data());
    EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
    return s.message();
  };
  EXPECT_NE(
      error({.box = BoundingBox{1, 0, 0, 1}, .width = 2, .height = 2}, 0, 1)
          .find("min_x < max_x"),
      std::string::npos);
  EXPECT_NE(
      error({.box = BoundingBox{0, 0, NAN, 1}, .width = 2, .height = 2}, 0, 1)
          .find("finite"),
      std::string::npos);
  EXPECT_NE(error({.box = box, .width = 0, .height = 2}, 0, 1).find(">= 1"),
            std::string::npos);
  EXPECT_NE(error({.box = box, .width = 2, .height = 2}, 1, 2).find("within"),
            std::string::npos);
}

TEST(InterpolationTest, NearestIsTheNearestCornersValue) {
  const Dataset dataset = test::PlaneDataset(1000, 9);
  const auto engine = EngineFor(dataset);
  ASSERT_NE(engine, nullptr);
  const std::vector<Point2> queries =
      test::UniformQueries(BoundingBox{0, 0, 1, 1}, 2000, 4);
  std::vector<LocateResult> batch;
  ASSERT_TRUE(
      engine->LocateBatch(queries, &batch, nullptr, Interpolation::kNearest)
          .ok());
  for (size_t i = 0; i < queries.size(); ++i) {
    LocateResult r;
    ASSERT_TRUE(engine->Locate(queries[i], &r, Interpolation::kNearest).ok());
    if (!r.has_value) continue;
    int nearest = 0;
    for (int k = 1; k < 3; ++k) {
      const double dk = SquaredDistance(r.vertices[k], queries[i]);
      const double dn = SquaredDistance(r.vertices[nearest], queries[i]);
      if (dk < dn || (dk == dn && r.vertex_ids[k] < r.vertex_ids[nearest])) {
        nearest = k;
      }
    }
    EXPECT_EQ(r.value, dataset.values[r.vertex_ids[nearest]]) << i;
    EXPECT_EQ(batch[i].value, r.value) << i;
  }
}

TEST(InterpolationTest, NaturalNeighborReproducesThePlane) {
  const auto engine = EngineFor(test::PlaneDataset(1500, 2));
  ASSERT_NE(engine, nullptr);
  const std::vector<Point2> queries =
      test::UniformQueries(BoundingBox{0, 0, 1, 1}, 3000, 8);
  std::vector<LocateResult> batch;
  ASSERT_TRUE(engine
                  ->LocateBatch(queries, &batch, nullptr,
                                Interpolation::kNaturalNeighbor)
                  .ok());
  int valued = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    if (!batch[i].has_value) continue;
    ++valued;
    EXPECT_NEAR(batch[i].value, test::Plane(queries[i]), 1e-9) << i;
  }
  EXPECT_GT(valued, 2900);
}

TEST(InterpolationTest, NaturalNeighborOnAConstrainedDatasetIsRefused) {
  Dataset dataset = test::PlaneDataset(500, 2);
  dataset.constraints.breaklines.push_back(
      OnThePlane({{0.2, 0.2}, {0.8, 0.7}}));
  const auto engine = EngineFor(dataset);
  ASSERT_NE(engine, nullptr);
  LocateResult r;
  const Status s =
      engine->Locate({0.5, 0.5}, &r, Interpolation::kNaturalNeighbor);
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
  EXPECT_NE(s.message().find("Delaunay"), std::string::npos) << s.message();
  EXPECT_TRUE(engine->Locate({0.5, 0.5}, &r, Interpolation::kNearest).ok());
  std::vector<double> cell(1);
  EXPECT_EQ(engine
                ->RenderRows({.box = BoundingBox{0, 0, 1, 1},
                              .width = 1,
                              .height = 1,
                              .interpolation = Interpolation::kNaturalNeighbor},
                             0, 1, cell.data())
                .code(),
            Status::Code::kInvalidArgument);
}

}  // namespace
}  // namespace locator
