// Tile sets end to end (issue 30's equality test at CI's size): locator-build
// builds a dataset file out of core in many small tiles, locatord serves the
// manifest, and its answers are CGAL's own on the same file (triangle ids
// included) for the end-to-end query set, every tile's bounding-box corners
// and edge midpoints, and the midpoint of every edge between two tiles'
// vertices (where the halos meet). A client routing by GetTopology to two
// shards answers the same, and a shard refuses a point it does not serve
// (the router: locatord_router_test.cc). Bad tile sets fail startup naming
// why, and locator-build refuses bad flags and sources naming them.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "client/locator_client.h"
#include "common/channel_options.h"
#include "server/core/dataset/file_io.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"
#include "tests/server/main/tile_set_fixture.h"
#include "tests/testing/run_binary.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

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

TEST_F(LocatordTileSetTest, AClientRoutesByTopologyAsTheRouterDoes) {
  const std::string spec = "tiles=" + tiles_ + "/manifest.json";
  std::string manifest;
  ASSERT_TRUE(
      ReadWholeFile(tiles_ + "/manifest.json", "manifest", &manifest).ok());
  size_t tiles = 0;
  for (size_t at = manifest.find("\"cells\":"); at != std::string::npos;
       at = manifest.find("\"cells\":", at + 1)) {
    ++tiles;
  }
  ASSERT_GT(tiles, 8u);
  std::unique_ptr<ServerProcess> shard0, shard1, router;
  // A selector naming a tile the set does not have fails startup.
  const Status bad =
      StartLocatord(spec, {"--tiles", "4-" + std::to_string(tiles)}, &shard1);
  EXPECT_FALSE(bad.ok());
  EXPECT_THAT(bad.message(), HasSubstr("does not exist"));
  ASSERT_TRUE(StartLocatord(spec, {"--tiles", "0-3"}, &shard0).ok());
  ASSERT_TRUE(StartLocatord(spec, {"--tiles", "4-" + std::to_string(tiles - 1)},
                            &shard1)
                  .ok());
  ASSERT_TRUE(StartLocatord(spec,
                            {"--route", "--shards",
                             shard0->target() + "," + shard1->target()},
                            &router)
                  .ok());

  // A client asking a shard alone learns that it cannot route.
  RequestScope scope;
  scope.dataset = "tiles";
  const ChannelOptions to_shard{.target = shard0->target()};
  LocatorClient lost(CreateLocatorChannel(to_shard), std::chrono::seconds(5),
                     scope);
  EXPECT_EQ(lost.RouteByTopology(to_shard).error_code(),
            grpc::StatusCode::FAILED_PRECONDITION);

  // Routed by the router's topology, straight to the shards.
  const ChannelOptions to_router{.target = router->target()};
  LocatorClient client(CreateLocatorChannel(to_router),
                       std::chrono::seconds(30), scope);
  ASSERT_TRUE(client.RouteByTopology(to_router).ok());
  std::vector<Point2> queries = TestQueries();
  const std::vector<Point2> seams = TileSeamQueries(tiles_);
  queries.insert(queries.end(), seams.begin(), seams.end());
  std::vector<double> xs, ys;
  for (const Point2& q : queries) {
    xs.push_back(q.x);
    ys.push_back(q.y);
  }
  constexpr BatchColumns kEveryColumn{
      .vertex_ids = true, .barycentric = true, .values = true};
  v1::LocateBatchResponse response;
  ASSERT_TRUE(client.LocateBatch(xs, ys, kEveryColumn, &response).ok());
  ASSERT_EQ(response.types_size(), static_cast<int>(queries.size()));
  std::vector<LocateResult> answers;
  for (size_t i = 0; i < queries.size(); ++i) {
    answers.push_back(FromBatchRow(response, i));
  }
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(csv_, &reference).ok());
  EXPECT_EQ(reference->Disagreements(queries, answers, false), "");
  v1::LocateResponse one;
  ASSERT_TRUE(client.Locate(queries[7], &one).ok());
  EXPECT_EQ(one.triangle_id(), response.triangle_ids(7));
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