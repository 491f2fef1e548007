#include "tests/server/main/tile_set_fixture.h"

#include <gmock/gmock.h>

#include <algorithm>
#include <filesystem>
#include <utility>

#include "server/core/dataset/file_io.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tileset/tile_file.h"
#include "tests/server/main/hostile/hostile_values.h"
#include "tests/testing/run_binary.h"

namespace locator::test {

std::vector<v1::GridRequest> HostileGrids() {
  v1::GridRequest benign;
  benign.mutable_box()->set_min_x(0.1);
  benign.mutable_box()->set_min_y(0.2);
  benign.mutable_box()->set_max_x(0.9);
  benign.mutable_box()->set_max_y(0.7);
  benign.set_width(5);
  benign.set_height(4);
  using Field = void (*)(v1::GridRequest&, double);
  const Field fields[] = {
      [](v1::GridRequest& g, double v) { g.mutable_box()->set_min_x(v); },
      [](v1::GridRequest& g, double v) { g.mutable_box()->set_min_y(v); },
      [](v1::GridRequest& g, double v) { g.mutable_box()->set_max_x(v); },
      [](v1::GridRequest& g, double v) { g.mutable_box()->set_max_y(v); },
      [](v1::GridRequest& g, double v) { g.set_nodata(v); },
      [](v1::GridRequest& g, double v) {
        g.clear_width();
        g.clear_height();
        g.set_cell_size(v);
      }};
  std::vector<v1::GridRequest> grids;
  for (const double v : HostileCoordinates()) {
    for (const Field field : fields) {
      field(grids.emplace_back(benign), v);
    }
  }
  for (const auto& [width, height] : {std::pair<uint32_t, uint32_t>{0, 4},
                                      {5, 0},
                                      {5000, 2},
                                      {4294967295u, 4294967295u}}) {
    v1::GridRequest& g = grids.emplace_back(benign);
    g.set_width(width);
    g.set_height(height);
  }
  grids.emplace_back(benign).set_interpolation(
      static_cast<v1::Interpolation>(99));
  grids.emplace_back(benign).set_dataset(std::string(100000, 'x'));
  return grids;
}

std::vector<v1::ProfileRequest> HostileProfiles() {
  v1::ProfileRequest line;
  for (const Point2& p : {Point2{0.1, 0.1}, Point2{0.9, 0.8}}) {
    v1::Point* vertex = line.add_vertices();
    vertex->set_x(p.x);
    vertex->set_y(p.y);
  }
  std::vector<v1::ProfileRequest> profiles;
  for (const double v : HostileCoordinates()) {
    for (int field = 0; field < 4; ++field) {
      v1::Point& vertex =
          *profiles.emplace_back(line).mutable_vertices(field / 2);
      field % 2 == 0 ? vertex.set_x(v) : vertex.set_y(v);
    }
  }
  for (const uint32_t samples : {1u, 301u, 4294967295u}) {
    profiles.emplace_back(line).set_samples(samples);
  }
  profiles.emplace_back();  // no vertices
  return profiles;
}

std::vector<std::string> FilesIn(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Tile corners and border midpoints, and the midpoints of edges whose ends

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

v1::GridRequest GridAcrossTheTiles(uint32_t width, uint32_t height) {
  v1::GridRequest grid;
  grid.set_dataset("tiles");
  grid.mutable_box()->set_min_x(-0.1);
  grid.mutable_box()->set_min_y(0.05);
  grid.mutable_box()->set_max_x(1.1);
  grid.mutable_box()->set_max_y(0.95);
  grid.set_width(width);
  grid.set_height(height);
  grid.set_nodata(-1);
  return grid;
}

void LocatordTileSetTest::SetUp() {
  csv_ = dir_.path() + "/survey.csv";
  WriteUniformCsv(csv_, 20000, 9);
  tiles_ = dir_.path() + "/tiles";
  const BinaryResult built = RunBinary(
      LOCATOR_BUILD_PATH,
      {csv_, "--out", tiles_, "--tile-points", "1500", "--max-memory", "64M"});
  ASSERT_EQ(built.exit_code, 0) << built.err;
  EXPECT_THAT(built.out, ::testing::HasSubstr("20000 points"));
}

void LocatordTileSetTest::StartShardsAndRouter(
    const std::vector<std::string>& router_flags,
    const std::vector<std::string>& shard_flags,
    const ChannelSecurity& shard_security) {
  const std::string spec = "tiles=" + tiles_ + "/manifest.json";
  for (const auto& [tiles, shard] :
       {std::pair{"0/2", &shard0_}, std::pair{"1/2", &shard1_}}) {
    std::vector<std::string> flags = {"--tiles", tiles};
    flags.insert(flags.end(), shard_flags.begin(), shard_flags.end());
    ASSERT_TRUE(StartLocatord(spec, flags, shard, shard_security).ok());
  }
  std::vector<std::string> flags = {
      "--route", "--shards", shard0_->target() + "," + shard1_->target()};
  flags.insert(flags.end(), router_flags.begin(), router_flags.end());
  ASSERT_TRUE(StartLocatord(spec, flags, &router_).ok());
}

}  // namespace locator::test
