// The tiled build (server/core/tiling/tiled_build.h) against one global
// CGAL build: the union of the tiles' owned triangles is the global
// canonical triangulation, for inputs of every kind at several tile
// counts, and the serving mesh is the same array for array.

#include "server/core/tiling/tiled_build.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/mesh_check.h"
#include "server/core/tiling/canonical_delaunay.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

struct Input {
  std::string name;
  std::function<Dataset()> make;
};

// `n` uniform points of the unit square mapped to [lo, lo + scale]^2.
Dataset Scaled(size_t n, uint64_t seed, double lo, double scale) {
  Dataset ds = GenerateUniform(n, seed);
  for (Point2& p : ds.points) p = {lo + p.x * scale, lo + p.y * scale};
  return ds;
}

const Input kInputs[] = {
    {"uniform", [] { return test::PlaneDataset(20000, 11); }},
    {"clusters", [] { return GenerateClusters(20000, 6, 3); }},
    {"dense_cluster",
     [] { return test::DenseClusterDataset(4000, 6000, 1e-4, 2); }},
    {"grid", [] { return test::GridDataset(150); }},
    {"cocircular", [] { return test::CocircularDataset(); }},
    {"lines", [] { return test::LinesDataset(8000, 4); }},
    {"repeats",
     [] { return test::WithRepeats(test::PlaneDataset(6000, 5), 3, 6); }},
    {"grid_repeats",
     [] { return test::WithRepeats(test::GridDataset(60), 2, 7); }},
    {"far_from_origin", [] { return Scaled(5000, 8, 4.5e6, 1e-3); }},
    {"huge_extent",  // the box's width overflows a double
     [] {
       Dataset ds = Scaled(1500, 9, -1, 2);
       for (Point2& p : ds.points) p = {p.x * 1e308, p.y * 1e308};
       return ds;
     }},
    {"subnormal", [] { return Scaled(3000, 10, 0, 1e-305); }},
};

// Tile sizes, as a number of tiles to aim for (0: the default size).
struct Tiling {
  std::string name;
  size_t tiles;
  size_t cell_points;
};
const Tiling kTilings[] = {
    {"one_tile", 1, 4},           {"default", 0, 4},
    {"five_coarse_cells", 5, 16}, {"forty_fine_cells", 40, 1},
    {"two_hundred", 200, 4},
};

void PrintTo(const Input& input, std::ostream* out) { *out << input.name; }
void PrintTo(const Tiling& tiling, std::ostream* out) { *out << tiling.name; }

class TiledBuildTest
    : public ::testing::TestWithParam<std::tuple<Input, Tiling>> {};

TEST_P(TiledBuildTest, EqualsTheGlobalCanonicalTriangulation) {
  const auto& [input, tiling] = GetParam();
  const Dataset dataset = input.make();
  auto global = test::BuildTriangulation(dataset);
  ASSERT_NE(global, nullptr);
  TiledBuildOptions options;
  options.threads = 2;
  options.cell_points = tiling.cell_points;
  const size_t n = dataset.points.size();
  if (tiling.tiles > 0)
    options.tile_vertices = std::max<size_t>(n / tiling.tiles, 1);
  BuiltMesh built;
  TiledBuildStats stats;
  const Status s =
      BuildTiledMesh(dataset.points, dataset.values, options, &built, &stats);
  ASSERT_TRUE(s.ok()) << s.ToString();
  if (tiling.tiles >= 5) {
    EXPECT_GT(stats.tiles, 1u);
  }
  // The union of the owned triangles, as sets of vertex ids.
  EXPECT_EQ(test::TriangleSet(*built.mesh), test::TriangleSet(global->mesh()));
  // And the whole serving mesh, byte for byte.
  EXPECT_TRUE(
      CompareMeshArrays(built.mesh->arrays(), global->mesh().arrays()).ok());
  EXPECT_TRUE(CheckMeshArrays(built.mesh->arrays()).ok());
  EXPECT_EQ(CountNonCanonicalEdges(*built.mesh), 0u);
  EXPECT_EQ(built.facts.duplicates_merged, global->duplicates_merged());
  const auto sample = global->mesh().SampleEdges(kEdgeSampleSize);
  ASSERT_EQ(built.facts.edge_sample.size(), sample.size());
  ASSERT_FALSE(sample.empty());
  EXPECT_EQ(std::memcmp(built.facts.edge_sample.data(), sample.data(),
                        sample.size() * sizeof(sample[0])),
            0);
}

INSTANTIATE_TEST_SUITE_P(InputsAndTilings, TiledBuildTest,
                         ::testing::Combine(::testing::ValuesIn(kInputs),
                                            ::testing::ValuesIn(kTilings)),
                         [](const auto& info) {
                           return std::get<0>(info.param).name + "_" +
                                  std::get<1>(info.param).name;
                         });

// The mesh depends on the points only: every thread count, and every tile
// size that follows from it, gives the same arrays.
TEST(TiledBuildDeterminismTest, ThreadCountsGiveTheSameMesh) {
  for (const Dataset& dataset :
       {test::GridDataset(200), test::PlaneDataset(40000, 3)}) {
    BuiltMesh first;
    for (const unsigned threads : {1u, 3u, 4u}) {
      for (const size_t tile_vertices : {size_t{0}, size_t{1500}}) {
        TiledBuildOptions options;
        options.threads = threads;
        options.tile_vertices = tile_vertices;
        BuiltMesh built;
        ASSERT_TRUE(
            BuildTiledMesh(dataset.points, dataset.values, options, &built)
                .ok());
        if (!first.mesh) {
          first = std::move(built);
          continue;
        }
        EXPECT_TRUE(
            CompareMeshArrays(built.mesh->arrays(), first.mesh->arrays()).ok());
      }
    }
  }
}

TEST(TiledBuildHaloTest, ManyTilesGrowHalos) {
  const Dataset dataset = GenerateUniform(30000, 4);
  TiledBuildOptions options;
  options.threads = 2;
  options.tile_vertices = 1000;
  BuiltMesh built;
  TiledBuildStats stats;
  ASSERT_TRUE(BuildTiledMesh(dataset.points, {}, options, &built, &stats).ok());
  EXPECT_EQ(stats.tiles, 30u);
  EXPECT_GT(stats.halo_points, 0u);
  // A ring of cells and a little more: far less than the points again.
  EXPECT_LT(stats.halo_points, dataset.points.size() * 2);
  EXPECT_GE(stats.max_rounds, 1);
}

// Bad inputs fail as Triangulation::Build fails, word for word.
TEST(TiledBuildErrorTest, BadPointsFailAsTheCgalBuildDoes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Dataset values_mismatch = GenerateUniform(10, 1);
  values_mismatch.values = {1, 2};
  const Dataset bad[] = {
      test::PointsDataset({{0, 0}, {1, 0}, {nan, 1}}),
      test::PointsDataset(
          {{0, 0}, {1, 0}, {0, std::numeric_limits<double>::infinity()}}),
      values_mismatch,
      test::PointsDataset({}),
      test::PointsDataset({{0, 0}, {1, 1}, {0, 0}, {1, 1}}),
      test::PointsDataset({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {1, 1}}),
  };
  for (const Dataset& dataset : bad) {
    const Status cgal = Triangulation::Build(dataset).status();
    BuiltMesh built;
    const Status tiled =
        BuildTiledMesh(dataset.points, dataset.values, {}, &built);
    ASSERT_FALSE(cgal.ok());
    EXPECT_EQ(tiled.code(), cgal.code());
    EXPECT_EQ(tiled.message(), cgal.message());
  }
}

}  // namespace
}  // namespace locator
