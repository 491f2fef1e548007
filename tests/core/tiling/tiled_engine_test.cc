// The engine on meshes built in tiles: every answer agrees with CGAL's
// locate() on the global triangulation, at random points and where tiles
// meet (tile corners, edges between vertices of different tiles).

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/strategies/locator_factory.h"
#include "server/core/tiling/cells/sorted_points.h"
#include "server/core/tiling/tile_triangulation.h"
#include "server/core/tiling/tiled_build.h"
#include "tests/core/locator_checks.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

// Points where the tiles of `options` meet: the corners of cells on a
// tile's border, and the ends, midpoints and near-midpoints of the mesh's
// edges whose ends belong to different tiles.
std::vector<Point2> TileSeams(const Dataset& dataset,
                              const TiledBuildOptions& options,
                              const ServingMesh& mesh) {
  SortedPoints sorted;
  SortPoints(dataset.points, options.cell_points, 1, &sorted);
  const SortedPointsSource source(sorted);
  const size_t tile_vertices =
      options.tile_vertices > 0
          ? options.tile_vertices
          : TileVerticesFor(sorted.size(), options.threads);
  const std::vector<Tile> tiles = CutTiles(sorted.grid, source, tile_vertices);
  EXPECT_GT(tiles.size(), 1u);
  const CellGrid& grid = sorted.grid;
  std::vector<int> tile_of_cell(grid.num_cells());
  for (size_t t = 0; t < tiles.size(); ++t) {
    for (uint32_t c = tiles[t].first_cell; c < tiles[t].end_cell; ++c) {
      tile_of_cell[c] = static_cast<int>(t);
    }
  }
  const auto tile_at = [&](int64_t column, int64_t row) {
    const int64_t side = grid.side();
    if (column < 0 || row < 0 || column >= side || row >= side) return -1;
    return tile_of_cell[grid.Cell(uint32_t(column), uint32_t(row))];
  };
  const BoundingBox& box = grid.box();
  const auto at = [](double lo, double hi, double f) {
    return lo * (1 - f) + hi * f;
  };
  std::vector<Point2> seams;
  for (int64_t row = 0; row <= grid.side(); ++row) {
    for (int64_t column = 0; column <= grid.side(); ++column) {
      // The corner shared by cells (column - 1 .. column, row - 1 .. row).
      const int t = tile_at(column, row);
      if (t == tile_at(column - 1, row) && t == tile_at(column, row - 1) &&
          t == tile_at(column - 1, row - 1)) {
        continue;
      }
      seams.push_back({at(box.min_x, box.max_x, double(column) / grid.side()),
                       at(box.min_y, box.max_y, double(row) / grid.side())});
    }
  }
  const auto tile_of_vertex = [&](uint32_t v) {
    return std::upper_bound(tiles.begin(), tiles.end(), v,
                            [](uint32_t x, const Tile& tile) {
                              return x < tile.first_vertex;
                            }) -
           tiles.begin();
  };
  for (uint32_t f = 0; f < mesh.num_faces(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = mesh.Corner(f, Ccw(i)), b = mesh.Corner(f, Cw(i));
      if (tile_of_vertex(a) == tile_of_vertex(b)) continue;
      const Point2 p = mesh.arrays().points[a], q = mesh.arrays().points[b];
      const Point2 mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
      const double dx = (q.x - p.x) * 1e-9, dy = (q.y - p.y) * 1e-9;
      for (const Point2& s : {p, mid, Point2{mid.x - dy, mid.y + dx},
                              Point2{mid.x + dy, mid.y - dx}}) {
        seams.push_back(s);
      }
    }
  }
  return seams;
}

struct Case {
  std::string name;
  Dataset dataset;
};

class TiledEngineTest : public ::testing::TestWithParam<size_t> {
 protected:
  static std::vector<Case> Cases() {
    std::vector<Case> cases;
    cases.push_back({"uniform", test::PlaneDataset(100000, 21)});
    cases.push_back({"grid", test::GridDataset(320)});
    cases.push_back({"clusters", GenerateClusters(100000, 8, 5)});
    return cases;
  }
};

// Engine::Create builds plain point sets in tiles on build_threads
// threads; its answers, single and batched, agree with CGAL's.
TEST_P(TiledEngineTest, AnswersAgreeWithCgalAtSeamsAndEverywhere) {
  const Case c = Cases()[GetParam()];
  auto global = test::BuildTriangulation(c.dataset);
  ASSERT_NE(global, nullptr);
  EngineOptions options;
  options.build_threads = 2;
  StatusOr<std::unique_ptr<Engine>> created =
      Engine::Create(c.dataset, options);
  ASSERT_TRUE(created.ok()) << created.status().ToString();
  const std::unique_ptr<Engine> engine = *std::move(created);
  TiledBuildOptions tiled;
  tiled.threads = 2;
  std::vector<Point2> queries = TileSeams(c.dataset, tiled, global->mesh());
  const std::vector<Point2> random =
      test::UniformQueries(global->bounding_box().Inflated(0.1), 20000, 3);
  queries.insert(queries.end(), random.begin(), random.end());
  const test::TriangleIndex index(*global);
  std::vector<LocateResult> batch;
  ASSERT_TRUE(engine->LocateBatch(queries, &batch).ok());
  size_t wrong = 0;
  for (size_t k = 0; k < queries.size(); ++k) {
    const Point2& q = queries[k];
    const LocateResult ref = global->ReferenceLocate(q);
    LocateResult got;
    ASSERT_TRUE(engine->Locate(q, &got).ok());
    for (const LocateResult& answer : {got, batch[k]}) {
      const bool ok = global->Agrees(q, answer, ref) &&
                      test::AnswerIsConsistent(*global, index, q, answer);
      if (!ok && ++wrong <= 5) {
        ADD_FAILURE() << "got " << test::DescribeAnswer(q, answer)
                      << " reference " << test::DescribeAnswer(q, ref);
      }
    }
    // Inside a triangle, its id is the CGAL build's (both meshes are the
    // same arrays); on an edge or vertex either side may answer.
    if (ref.type == LocationType::kFace) {
      EXPECT_EQ(got.triangle_id, ref.triangle_id);
    }
  }
  EXPECT_EQ(wrong, 0u) << "of " << queries.size();
}

constexpr const char* kCaseNames[] = {"uniform", "grid", "clusters"};
INSTANTIATE_TEST_SUITE_P(Datasets, TiledEngineTest, ::testing::Values(0, 1, 2),
                         [](const auto& info) {
                           return std::string(kCaseNames[info.param]);
                         });

// Strategies on a mesh of many small tiles (more seams than points per
// tile) agree with CGAL, at its seams and at random points.
TEST(TiledMeshTest, StrategiesAgreeWithCgalOnManySmallTiles) {
  for (const Dataset& dataset :
       {test::GridDataset(70),
        test::WithRepeats(GenerateUniform(4000, 6), 1, 2),
        test::LinesDataset(3000, 9), test::CocircularDataset()}) {
    auto global = test::BuildTriangulation(dataset);
    ASSERT_NE(global, nullptr);
    TiledBuildOptions options;
    options.threads = 2;
    options.tile_vertices = 150;
    BuiltMesh built;
    ASSERT_TRUE(
        BuildTiledMesh(dataset.points, dataset.values, options, &built).ok());
    std::vector<Point2> queries = TileSeams(dataset, options, *built.mesh);
    const std::vector<Point2> random =
        test::UniformQueries(global->bounding_box().Inflated(0.2), 1000, 4);
    queries.insert(queries.end(), random.begin(), random.end());
    for (const std::string strategy :
         {"walk", "jump-and-walk", "self-tuning"}) {
      const StatusOr<std::unique_ptr<PointLocator>> locator =
          MakePointLocator(strategy, *built.mesh, TuningOptions());
      ASSERT_TRUE(locator.ok());
      test::ExpectAllAgree(**locator, *global, queries);
    }
  }
}

}  // namespace
}  // namespace locator
