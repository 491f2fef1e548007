// The out-of-core tile-set build (server/core/tileset/) against one global
// CGAL build: the union of the tile files' triangles is the global
// canonical triangulation, ids and values are the dataset's, whatever the
// bins and tiles; a killed build resumes from what it wrote; bad points
// fail as the in-memory builds fail.

#include "server/core/tileset/tileset_build.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/orientation.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/dataset/dataset_fingerprint.h"
#include "server/core/dataset/file_io.h"
#include "server/core/mesh/mesh_file.h"
#include "server/core/tileset/tile_file.h"
#include "server/core/tileset/tileset_manifest.h"
#include "server/core/tiling/tiled_build.h"
#include "tests/core/scratch_dir.h"
#include "tests/core/test_datasets.h"

namespace locator {
namespace {

// What a tile set's files hold, joined in vertex order.
struct TileSetContents {
  std::vector<Point2> points;
  std::vector<uint32_t> ids;
  std::vector<double> values;
  // Corners as global vertex indices.
  std::vector<MeshTriangle> triangles;
};

void ReadTileSetFiles(const std::string& dir, const TileSetManifest& manifest,
                      TileSetContents* out) {
  for (const TileSetManifest::TileEntry& entry : manifest.tiles) {
    std::string bytes;
    ASSERT_TRUE(ReadWholeFile(dir + "/" + entry.file, "tile", &bytes).ok());
    TileFileInfo info;
    TileFileArrays arrays;
    const Status decoded = DecodeTileFile(bytes, &info, &arrays);
    ASSERT_TRUE(decoded.ok()) << decoded.ToString();
    ASSERT_EQ(info.tile.first_vertex, out->points.size());
    EXPECT_EQ(info.checksum, entry.info.checksum);
    EXPECT_EQ(info.build_key, manifest.build_key);
    out->points.insert(out->points.end(), arrays.points.begin(),
                       arrays.points.end());
    out->ids.insert(out->ids.end(), arrays.ids.begin(), arrays.ids.end());
    out->values.insert(out->values.end(), arrays.values.begin(),
                       arrays.values.end());
    out->triangles.insert(out->triangles.end(), arrays.triangles.begin(),
                          arrays.triangles.end());
  }
}

Status BuildFromDataset(const Dataset& dataset, const std::string& dir,
                        const TileSetOptions& options,
                        TileSetManifest* manifest,
                        TileSetStats* stats = nullptr) {
  auto stream = DatasetPointStream(dataset);
  return BuildTileSet(
      stream.get(), {"test " + dataset.source, "test", ""}, dir, options,
      [](const TileSetProgress&) {}, manifest, stats);
}

struct TileSetCase {
  const char* name;
  Dataset (*make)();
  TileSetOptions options;
};

TileSetOptions TileSetOptionsOf(size_t memory_bytes, size_t tile_points,
                                unsigned threads) {
  TileSetOptions options;
  options.memory_bytes = memory_bytes;
  options.tile_points = tile_points;
  options.threads = threads;
  return options;
}

// Small memory makes many bins (memory / 80 points each, at least 2^15).
const TileSetCase kTileSetCases[] = {
    {"uniform_values", [] { return test::PlaneDataset(60000, 11); },
     TileSetOptionsOf(size_t{1} << 20, 3000, 2)},
    {"clusters", [] { return GenerateClusters(50000, 6, 3); },
     TileSetOptionsOf(size_t{1} << 20, 5000, 1)},
    {"grid_repeats",
     [] { return test::WithRepeats(test::GridDataset(150), 2, 7); },
     TileSetOptionsOf(size_t{1} << 20, 2000, 2)},
    {"lines", [] { return test::LinesDataset(8000, 4); },
     TileSetOptionsOf(size_t{64} << 20, 1000, 2)},
};

class TileSetBuildTest : public ::testing::TestWithParam<TileSetCase> {};

TEST_P(TileSetBuildTest, TilesAreTheGlobalCanonicalTriangulation) {
  const TileSetCase& c = GetParam();
  const Dataset dataset = c.make();
  auto global = test::BuildTriangulation(dataset);
  ASSERT_NE(global, nullptr);
  test::ScratchDir dir;
  TileSetManifest manifest;
  TileSetStats stats;
  const Status built =
      BuildFromDataset(dataset, dir.path(), c.options, &manifest, &stats);
  ASSERT_TRUE(built.ok()) << built.ToString();
  EXPECT_GT(manifest.tiles.size(), 1u);
  // Bins of 2^15 points (the least) when memory is short.
  if (c.options.memory_bytes <= (size_t{1} << 20)) {
    EXPECT_GT(stats.bins, 1u);
  }
  EXPECT_EQ(manifest.fingerprint, DatasetFingerprint(dataset));
  EXPECT_EQ(manifest.input_points, dataset.points.size());
  EXPECT_EQ(manifest.input_points - manifest.vertices,
            global->duplicates_merged());
  // What a server routes by reads back from the manifest exactly.
  TileSetManifestSummary summary;
  ASSERT_TRUE(ParseManifestSummary(ManifestJson(manifest), "m", &summary).ok());
  EXPECT_EQ(summary.bounds.min_x, manifest.bounds.min_x);
  EXPECT_EQ(summary.bounds.max_y, manifest.bounds.max_y);
  EXPECT_EQ(summary.grid_level, manifest.grid_level);
  ASSERT_EQ(summary.tile_first_cells.size(), manifest.tiles.size());
  for (size_t t = 0; t < manifest.tiles.size(); ++t) {
    EXPECT_EQ(summary.tile_first_cells[t],
              manifest.tiles[t].info.tile.first_cell);
  }
  // Tiles whose cells leave a gap are refused.
  TileSetManifest gap = manifest;
  gap.tiles[1].info.tile.first_cell += 1;
  EXPECT_THAT(ParseManifestSummary(ManifestJson(gap), "m", &summary).message(),
              ::testing::HasSubstr("cells do not follow each other"));
  // The working files are gone; the manifest and tiles stay.
  EXPECT_FALSE(std::filesystem::exists(dir.path() + "/work"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() + "/manifest.json"));

  TileSetContents contents;
  ReadTileSetFiles(dir.path(), manifest, &contents);
  ASSERT_EQ(contents.points.size(), manifest.vertices);
  for (size_t v = 0; v < contents.points.size(); ++v) {
    const uint32_t id = contents.ids[v];
    ASSERT_LT(id, dataset.points.size());
    EXPECT_EQ(contents.points[v].x, dataset.points[id].x);
    EXPECT_EQ(contents.points[v].y, dataset.points[id].y);
    if (dataset.has_values()) {
      EXPECT_EQ(contents.values[v], dataset.values[id]);
    }
  }
  std::vector<std::array<uint32_t, 3>> triangles;
  for (const MeshTriangle& t : contents.triangles) {
    std::array<uint32_t, 3> ids;
    for (int i = 0; i < 3; ++i) {
      ASSERT_LT(t.corner[i], contents.points.size());
      ids[i] = contents.ids[t.corner[i]];
    }
    EXPECT_EQ(
        Orientation(contents.points[t.corner[0]], contents.points[t.corner[1]],
                    contents.points[t.corner[2]]),
        Side::kLeft);
    std::sort(ids.begin(), ids.end());
    triangles.push_back(ids);
  }
  std::sort(triangles.begin(), triangles.end());
  EXPECT_EQ(triangles, test::TriangleSet(global->mesh()));

  // The assembled mesh file is the one a build in memory writes, byte for
  // byte (so its arrays are Triangulation::Build's, tiled_build_test.cc).
  BuiltMesh in_memory;
  ASSERT_TRUE(
      BuildTiledMesh(dataset.points, dataset.values, {}, &in_memory).ok());
  const std::string expected_path = dir.path() + "/expected.mesh";
  ASSERT_TRUE(
      WriteMeshFile(expected_path, manifest.fingerprint, in_memory).ok());
  std::string expected, assembled;
  ASSERT_TRUE(ReadWholeFile(expected_path, "mesh", &expected).ok());
  ASSERT_TRUE(
      ReadWholeFile(dir.path() + "/" + manifest.mesh_file, "mesh", &assembled)
          .ok());
  EXPECT_EQ(assembled.size(), expected.size());
  EXPECT_TRUE(assembled == expected);
}

INSTANTIATE_TEST_SUITE_P(Datasets, TileSetBuildTest,
                         ::testing::ValuesIn(kTileSetCases),
                         [](const auto& info) { return info.param.name; });

TEST(TileSetResumeTest, AKilledBuildKeepsWhatItWrote) {
  const Dataset dataset = test::PlaneDataset(40000, 5);
  test::ScratchDir dir;
  const TileSetOptions options = TileSetOptionsOf(size_t{1} << 20, 4000, 1);
  // A directory where tile 3 goes makes its write fail, as a kill would
  // have stopped the build there.
  std::filesystem::create_directories(dir.path() + "/tile-00003.tile/x");
  TileSetManifest manifest;
  TileSetStats stats;
  const Status failed =
      BuildFromDataset(dataset, dir.path(), options, &manifest, &stats);
  ASSERT_EQ(failed.code(), Status::Code::kIOError) << failed.ToString();
  EXPECT_NE(failed.message().find("tile-00003.tile"), std::string::npos)
      << failed.message();
  EXPECT_FALSE(std::filesystem::exists(dir.path() + "/manifest.json"));

  std::filesystem::remove_all(dir.path() + "/tile-00003.tile");
  const Status resumed =
      BuildFromDataset(dataset, dir.path(), options, &manifest, &stats);
  ASSERT_TRUE(resumed.ok()) << resumed.ToString();
  EXPECT_TRUE(stats.bins_reused);
  EXPECT_EQ(stats.tiles_reused, manifest.tiles.size() - 1);

  // The same as a build from scratch.
  test::ScratchDir fresh;
  TileSetManifest expected;
  ASSERT_TRUE(BuildFromDataset(dataset, fresh.path(), options, &expected).ok());
  // Tiles, checksums, bounds and statistics alike; only the time differs.
  manifest.build_seconds = expected.build_seconds = 0;
  EXPECT_EQ(ManifestJson(manifest), ManifestJson(expected));
}

TEST(TileSetResumeTest, TilesOfAnotherBuildAreRebuilt) {
  const Dataset dataset = test::PlaneDataset(20000, 6);
  test::ScratchDir dir;
  TileSetManifest manifest;
  TileSetStats stats;
  ASSERT_TRUE(BuildFromDataset(dataset, dir.path(),
                               TileSetOptionsOf(size_t{1} << 20, 4000, 1),
                               &manifest)
                  .ok());
  // Other tile sizes: other tiles, none of the old files fits.
  ASSERT_TRUE(BuildFromDataset(dataset, dir.path(),
                               TileSetOptionsOf(size_t{1} << 20, 3000, 1),
                               &manifest, &stats)
                  .ok());
  EXPECT_EQ(stats.tiles_reused, 0u);
  EXPECT_FALSE(stats.bins_reused);
}

TEST(TileSetBuildErrorTest, BadPointsAreRefusedNamingThem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct BadPoints {
    std::vector<Point2> points;
    const char* says;
  };
  const BadPoints bad[] = {
      {{{0, 0}, {1, 0}, {nan, 1}}, "point 2 has a non-finite coordinate"},
      {{}, "no points"},
      {{{0, 0}, {1, 1}, {0, 0}, {1, 1}}, "3"},
      {{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, "collinear"},
  };
  for (const BadPoints& b : bad) {
    test::ScratchDir dir;
    TileSetManifest manifest;
    const Status s = BuildFromDataset(test::PointsDataset(b.points), dir.path(),
                                      TileSetOptions(), &manifest);
    EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
    EXPECT_NE(s.message().find(b.says), std::string::npos) << s.message();
  }
}

}  // namespace
}  // namespace locator
