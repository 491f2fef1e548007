// Tile sets end to end (issue 30's equality test at CI's size): locator-build
// builds a dataset file out of core in many small tiles, locatord serves the
// manifest, and its answers are CGAL's own on the same file (triangle ids
// included) for the end-to-end query set, every tile's bounding-box corners
// and edge midpoints, and the midpoint of every edge between two tiles'
// vertices (where the halos meet). Bad tile sets fail startup naming why,
// and locator-build refuses bad flags and sources naming them.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "server/core/dataset/file_io.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tileset/tile_file.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"
#include "tests/testing/run_binary.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

// The names of the files in `dir`, sorted.
std::vector<std::string> FilesIn(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Tile corners and border midpoints, and the midpoints of edges whose ends
// are in different tiles, read from the tile files in `dir`.
std::vector<Point2> TileSeamQueries(const std::string& dir) {
  std::vector<std::string> bytes;
  std::vector<TileFileArrays> tiles;
  std::vector<Point2> points;  // all vertices, in order
  for (const std::string& name : FilesIn(dir)) {
    if (!name.ends_with(".tile")) continue;
    bytes.emplace_back();
    EXPECT_TRUE(ReadWholeFile(dir + "/" + name, "tile", &bytes.back()).ok());
  }
  std::vector<Point2> queries;
  std::vector<uint32_t> tile_end;
  for (const std::string& b : bytes) {
    TileFileInfo info;
    TileFileArrays arrays;
    EXPECT_TRUE(DecodeTileFile(b, &info, &arrays).ok());
    tiles.push_back(arrays);
    tile_end.push_back(info.tile.end_vertex);
    points.insert(points.end(), arrays.points.begin(), arrays.points.end());
    BoundingBox box;
    for (const Point2& p : arrays.points) box.Extend(p);
    const double xs[] = {box.min_x, (box.min_x + box.max_x) / 2, box.max_x};
    const double ys[] = {box.min_y, (box.min_y + box.max_y) / 2, box.max_y};
    for (const double x : xs) {
      for (const double y : ys) queries.push_back({x, y});
    }
  }
  const auto tile_of = [&](uint32_t v) {
    return std::upper_bound(tile_end.begin(), tile_end.end(), v) -
           tile_end.begin();
  };
  for (const TileFileArrays& tile : tiles) {
    for (const MeshTriangle& t : tile.triangles) {
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = t.corner[i], b = t.corner[(i + 1) % 3];
        if (tile_of(a) == tile_of(b)) continue;
        queries.push_back(
            {(points[a].x + points[b].x) / 2, (points[a].y + points[b].y) / 2});
        queries.push_back(points[a]);
      }
    }
  }
  return queries;
}

class LocatordTileSetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    csv_ = dir_.path() + "/survey.csv";
    WriteUniformCsv(csv_, 20000, 9);
    tiles_ = dir_.path() + "/tiles";
    const BinaryResult built =
        RunBinary(LOCATOR_BUILD_PATH, {csv_, "--out", tiles_, "--tile-points",
                                       "1500", "--max-memory", "64M"});
    ASSERT_EQ(built.exit_code, 0) << built.err;
    EXPECT_THAT(built.out, HasSubstr("20000 points"));
  }

  ScratchDir dir_;
  std::string csv_;
  std::string tiles_;
};

TEST_F(LocatordTileSetTest, AnswersAsCgalOnTheWholeDatasetAcrossTiles) {
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(
      StartLocatord("tiles=" + tiles_ + "/manifest.json", {}, &server).ok());
  auto stub = NewStub(*server);
  ExpectAnswersAgree(*stub, csv_, "tiles");

  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(csv_, &reference).ok());
  std::vector<Point2> queries = TestQueries();
  const std::vector<Point2> seams = TileSeamQueries(tiles_);
  EXPECT_GT(seams.size(), 1000u);
  queries.insert(queries.end(), seams.begin(), seams.end());
  const std::vector<LocateResult> answers =
      LocateInBatches(*stub, queries, 4096);
  ASSERT_EQ(answers.size(), queries.size());
  EXPECT_EQ(reference->Disagreements(queries, answers, false), "");

  const v1::GetStatsResponse stats = GetStats(*stub, "tiles");
  EXPECT_EQ(stats.dataset().input_points(), 20000u);
  EXPECT_EQ(stats.dataset().source(), csv_);
}

TEST_F(LocatordTileSetTest, ABadTileSetFailsStartupNamingIt) {
  // The mesh file gone: the manifest names what is missing.
  for (const std::string& name : FilesIn(tiles_)) {
    if (name.ends_with(".mesh")) std::remove((tiles_ + "/" + name).c_str());
  }
  std::unique_ptr<ServerProcess> server;
  Status started =
      StartLocatord("tiles=" + tiles_ + "/manifest.json", {}, &server);
  EXPECT_FALSE(started.ok());
  EXPECT_THAT(started.message(), HasSubstr(".mesh"));

  // Not a manifest at all.
  std::ofstream(tiles_ + "/manifest.json") << "{\"format\":\"geojson\"}";
  started = StartLocatord("tiles=" + tiles_ + "/manifest.json", {}, &server);
  EXPECT_FALSE(started.ok());
  EXPECT_THAT(started.message(), HasSubstr("not a locator tile-set manifest"));
}

// locator-build's own refusals: bad flags (exit 2), and a source it cannot
// tile or read (exit 1), each named.
TEST(LocatorBuildTest, RefusesWhatItCannotBuildNamingIt) {
  ScratchDir dir;
  const std::string out = dir.path() + "/tiles";
  BinaryResult result = RunBinary(LOCATOR_BUILD_PATH, {"--out", out});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, HasSubstr("give exactly one SOURCE"));
  result = RunBinary(LOCATOR_BUILD_PATH, {"uniform:1000"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, HasSubstr("--out DIR is required"));

  const std::string csv = dir.path() + "/points.csv";
  WriteUniformCsv(csv, 500, 3);
  const std::string wkt = dir.path() + "/road.wkt";
  std::ofstream(wkt) << "LINESTRING (0.1 0.1, 0.9 0.9)\n";
  result = RunBinary(LOCATOR_BUILD_PATH, {csv + "+" + wkt, "--out", out});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("plain point sets only"));

  const std::string bad = dir.path() + "/bad.csv";
  std::ofstream(bad) << "0,0\n1,0\n0,nan\n";
  result = RunBinary(LOCATOR_BUILD_PATH, {bad, "--out", out});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("bad.csv:3"));
}

}  // namespace
}  // namespace locator::test
