// Tile sets end to end (issue 30's equality test at CI's size): locator-build
// builds a dataset file out of core in many small tiles, locatord serves the
// manifest, and its answers are CGAL's own on the same file (triangle ids
// included) for the end-to-end query set, every tile's bounding-box corners
// and edge midpoints, and the midpoint of every edge between two tiles'
// vertices (where the halos meet). Sharded (two locatord --tiles behind a
// locatord --route, or a client routing by GetTopology) it answers the
// same, and a shard refuses a point it does not serve. Bad tile sets fail
// startup naming why, and locator-build refuses bad flags and sources
// naming them.

#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "client/locator_client.h"
#include "common/channel_options.h"
#include "server/core/dataset/file_io.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tileset/tile_file.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/http/http_test_client.h"
#include "tests/server/main/e2e_support.h"
#include "tests/testing/run_binary.h"
#include "tests/testing/test_pki.h"

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

  // Two shards (--tiles 0/2 and 1/2) of the tile set, with `shard_flags`
  // added (and probed with `shard_security`), and a router over them with
  // `router_flags` added.
  void StartShardsAndRouter(const std::vector<std::string>& router_flags,
                            const std::vector<std::string>& shard_flags = {},
                            const ChannelSecurity& shard_security = {}) {
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

  ScratchDir dir_;
  std::string csv_;
  std::string tiles_;
  std::unique_ptr<ServerProcess> shard0_, shard1_, router_;
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

TEST_F(LocatordTileSetTest, ShardsBehindARouterAnswerAsTheWholeSet) {
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter({"--max-batch-points", "5000"}));
  ServerProcess& shard0 = *shard0_;
  ServerProcess& shard1 = *shard1_;
  auto stub = NewStub(*router_);

  // The router lists both shards, each with its half of the tiles.
  v1::GetTopologyRequest topology_request;
  topology_request.set_dataset("tiles");
  v1::GetTopologyResponse topology;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(stub->GetTopology(&context, topology_request, &topology).ok());
  }
  EXPECT_TRUE(topology.tiled());
  EXPECT_TRUE(topology.complete());
  ASSERT_EQ(topology.shards_size(), 2);
  EXPECT_EQ(topology.shards(0).target(), shard0.target());
  const int tiles = topology.tiles_size();
  EXPECT_GT(tiles, 8);
  EXPECT_EQ(topology.shards(0).tiles_size() + topology.shards(1).tiles_size(),
            tiles);
  // A shard knows only its own tiles.
  v1::GetTopologyResponse own;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(
        NewStub(shard1)->GetTopology(&context, topology_request, &own).ok());
  }
  EXPECT_FALSE(own.complete());
  ASSERT_EQ(own.shards_size(), 1);
  EXPECT_EQ(own.shards(0).target(), "");
  EXPECT_EQ(own.shards(0).tiles(0), static_cast<uint32_t>(tiles / 2));

  // Through the router, CGAL's answers on the whole dataset, seams too.
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(csv_, &reference).ok());
  std::vector<Point2> queries = TestQueries();
  const std::vector<Point2> seams = TileSeamQueries(tiles_);
  queries.insert(queries.end(), seams.begin(), seams.end());
  std::vector<LocateResult> answers = LocateInBatches(*stub, queries, 4096);
  ASSERT_EQ(answers.size(), queries.size());
  EXPECT_EQ(reference->Disagreements(queries, answers, false), "");
  const std::span<const Point2> first(queries.data(), 300);
  answers = LocateEach(*stub, first);
  EXPECT_EQ(reference->Disagreements(first, answers, false), "");

  // A shard sent every point refuses those of the other shard's tiles.
  v1::LocateBatchRequest all = BatchRequestFor(queries);
  all.set_dataset("tiles");
  v1::LocateBatchResponse refused;
  grpc::ClientContext context;
  const grpc::Status status =
      NewStub(shard0)->LocateBatch(&context, all, &refused);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_THAT(status.error_message(),
              HasSubstr("which this server does not serve (--tiles '0/2')"));

  // Hostile requests get a server's answers, naming the point's index in
  // the whole batch, not in a shard's part.
  const auto batch_status = [&](const std::vector<Point2>& points,
                                const std::string& dataset) {
    v1::LocateBatchRequest request = BatchRequestFor(points);
    request.set_dataset(dataset);
    v1::LocateBatchResponse response;
    grpc::ClientContext context;
    return stub->LocateBatch(&context, request, &response);
  };
  std::vector<Point2> hostile(3000, Point2{0.5, 0.5});
  hostile[2999] = {std::numeric_limits<double>::quiet_NaN(), 0.5};
  grpc::Status answer = batch_status(hostile, "tiles");
  EXPECT_EQ(answer.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(answer.error_message(), HasSubstr("point 2999"));
  answer = batch_status(std::vector<Point2>(5001, Point2{0.5, 0.5}), "tiles");
  EXPECT_EQ(answer.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  EXPECT_THAT(answer.error_message(), HasSubstr("limit of 5000 points"));
  EXPECT_EQ(
      batch_status({{0.5, 0.5}}, "lava\n" + std::string(300, 'z')).error_code(),
      grpc::StatusCode::NOT_FOUND);
  EXPECT_TRUE(batch_status({{1e300, -1e300}, {4.9e-324, 0}}, "tiles").ok());
  v1::LocateRequest no_point;
  v1::LocateResponse located;
  grpc::ClientContext no_point_context;
  EXPECT_EQ(stub->Locate(&no_point_context, no_point, &located).error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);

  // What the router cannot route is refused, saying what to do instead.
  v1::LocateBatchRequest with_crs = BatchRequestFor(first);
  with_crs.set_crs("EPSG:4326");
  grpc::ClientContext crs_context;
  EXPECT_EQ(stub->LocateBatch(&crs_context, with_crs, &refused).error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);
  // A grid is streamed from one shard, which answers it whole: as a
  // shard called directly answers it. Blocks of rows come in any order,
  // so the grids are compared whole.
  v1::GridRequest grid;
  grid.set_dataset("tiles");
  grid.mutable_box()->set_min_x(-0.1);
  grid.mutable_box()->set_min_y(0.05);
  grid.mutable_box()->set_max_x(1.1);
  grid.mutable_box()->set_max_y(0.95);
  grid.set_width(300);
  grid.set_height(700);
  grid.set_nodata(-1);
  v1::GridResponse routed_grid, shard_grid;
  int routed_messages = 0;
  ASSERT_TRUE(StreamGrid(*stub, grid, &routed_grid, &routed_messages).ok());
  ASSERT_GT(routed_messages, 1);  // a header and rows, in messages
  ASSERT_TRUE(StreamGrid(*NewStub(shard1), grid, &shard_grid).ok());
  EXPECT_EQ(routed_grid.header().SerializeAsString(),
            shard_grid.header().SerializeAsString());
  ASSERT_EQ(routed_grid.values_size(), 300 * 700);
  ASSERT_EQ(shard_grid.values_size(), routed_grid.values_size());
  for (int v = 0; v < routed_grid.values_size(); ++v) {
    // A cell on an edge may take its value from either face.
    ASSERT_NEAR(routed_grid.values(v), shard_grid.values(v), 1e-9)
        << "cell " << v;
  }
  // The shard's refusal reaches the caller naming the shard; a caller that
  // stops reading and cancels leaves the router serving.
  v1::GridRequest empty = grid;
  empty.set_width(0);
  grpc::ClientContext empty_context;
  v1::GridResponse unused;
  auto empty_reader = stub->Grid(&empty_context, empty);
  while (empty_reader->Read(&unused)) {
  }
  const grpc::Status empty_status = empty_reader->Finish();
  EXPECT_EQ(empty_status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(empty_status.error_message(), HasSubstr("shard "));
  for (int call = 0; call < 3; ++call) {
    grpc::ClientContext cancelled;
    auto reader = stub->Grid(&cancelled, grid);
    ASSERT_TRUE(reader->Read(&unused));
    cancelled.TryCancel();
    EXPECT_EQ(reader->Finish().error_code(), grpc::StatusCode::CANCELLED);
  }
  v1::GridResponse again;
  int again_messages = 0;
  EXPECT_TRUE(StreamGrid(*stub, grid, &again, &again_messages).ok());
  EXPECT_EQ(again_messages, routed_messages);

  grpc::ClientContext retune_context;
  v1::RetuneResponse retuned;
  const grpc::Status retune =
      stub->Retune(&retune_context, v1::RetuneRequest(), &retuned);
  EXPECT_EQ(retune.error_code(), grpc::StatusCode::UNIMPLEMENTED);
  EXPECT_THAT(retune.error_message(), HasSubstr("call a shard"));
}

// Shards that serve mutual TLS only are reached by a router given the
// --shard-tls flags (the CA, and its client certificate and key); a router
// without them is told why it cannot reach a shard.
TEST_F(LocatordTileSetTest, TheRouterReachesTlsShardsWithTheShardTlsFlags) {
  std::unique_ptr<TestPki> pki;
  ASSERT_TRUE(TestPki::Create(&pki).ok());
  ASSERT_NO_FATAL_FAILURE(
      StartShardsAndRouter(pki->ClientFlags(/*client_cert=*/true, "shard-"),
                           pki->ServerFlags(/*mutual=*/true),
                           pki->ClientSecurity(/*client_cert=*/true)));
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(csv_, &reference).ok());
  const std::vector<Point2> queries = TestQueries();
  const std::vector<LocateResult> answers =
      LocateInBatches(*NewStub(*router_), queries, 4096);
  ASSERT_EQ(answers.size(), queries.size());
  EXPECT_EQ(reference->Disagreements(queries, answers, false), "");

  std::unique_ptr<ServerProcess> plaintext_router;
  ASSERT_TRUE(StartLocatord("tiles=" + tiles_ + "/manifest.json",
                            {"--route", "--shards",
                             shard0_->target() + "," + shard1_->target()},
                            &plaintext_router)
                  .ok());
  const std::vector<Point2> middle = {{0.5, 0.5}};
  v1::LocateBatchRequest request = BatchRequestFor(middle);
  request.set_dataset("tiles");
  v1::LocateBatchResponse response;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() +
                       std::chrono::seconds(30));
  const grpc::Status refused =
      NewStub(*plaintext_router)->LocateBatch(&context, request, &response);
  EXPECT_EQ(refused.error_code(), grpc::StatusCode::UNAVAILABLE);
  EXPECT_THAT(refused.error_message(),
              HasSubstr("shard 0 (" + shard0_->target() + ")"));
}

// The router's HTTP/JSON API answers browsers as the gRPC router does.
TEST_F(LocatordTileSetTest, TheRouterAnswersOverHttpAsOverGrpc) {
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter(
      {"--http-listen", "127.0.0.1:0", "--http-max-body-bytes", "4096"}));
  auto stub = NewStub(*router_);
  ASSERT_TRUE(router_->WaitForListening().ok());  // its HTTP line
  const int http_port = router_->port();

  const std::vector<Point2> points = {
      {0.1, 0.1}, {0.9, 0.1}, {0.5, 0.5}, {0.9, 0.9}, {3, -2}};
  v1::LocateBatchRequest request = BatchRequestFor(points);
  request.set_dataset("tiles");
  v1::LocateBatchResponse over_grpc;
  grpc::ClientContext context;
  ASSERT_TRUE(stub->LocateBatch(&context, request, &over_grpc).ok());
  request.clear_dataset();
  std::string body;
  ASSERT_TRUE(google::protobuf::util::MessageToJsonString(request, &body).ok());
  HttpReply reply;
  ASSERT_TRUE(SendHttp(http_port, "POST", "/v1/datasets/tiles:locateBatch",
                       &reply, body)
                  .ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  v1::LocateBatchResponse over_http;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(reply.body, &over_http).ok());
  EXPECT_EQ(over_http.triangle_ids_size(), 5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(over_http.triangle_ids(i), over_grpc.triangle_ids(i)) << i;
    EXPECT_EQ(over_http.types(i), over_grpc.types(i)) << i;
  }
  ASSERT_TRUE(
      SendHttp(http_port, "GET", "/v1/datasets/tiles:topology", &reply).ok());
  EXPECT_EQ(reply.status, 200u);
  EXPECT_THAT(reply.body, HasSubstr("\"complete\":true"));
  // A shard's own routes are not the router's; bad bodies are 400.
  ASSERT_TRUE(
      SendHttp(http_port, "GET", "/v1/datasets/tiles/tiles/0/0/0.png", &reply)
          .ok());
  EXPECT_EQ(reply.status, 404u);
  EXPECT_THAT(reply.body, HasSubstr("answered by any shard"));
  ASSERT_TRUE(SendHttp(http_port, "POST", "/v1/datasets/tiles:locate", &reply,
                       "{\"point\": {\"x\": \"NaN\", \"y\": 1}}")
                  .ok());
  EXPECT_EQ(reply.status, 400u) << reply.body;
  ASSERT_TRUE(SendHttp(http_port, "POST", "/v1/datasets/tiles:locate", &reply,
                       "{\"pont\": 1}")
                  .ok());
  EXPECT_EQ(reply.status, 400u) << reply.body;
  ASSERT_TRUE(SendHttp(http_port, "POST", "/v1/datasets/tiles:locate", &reply,
                       "{\"point\": {\"x\": \"Infinity\", \"y\": 1}}")
                  .ok());
  EXPECT_EQ(reply.status, 400u) << reply.body;
  // A body past --http-max-body-bytes is refused before it is read whole.
  const std::string big = "{\"xs\": [" + std::string(5000, ' ') + "]}";
  ASSERT_TRUE(
      SendHttp(http_port, "POST", "/v1/datasets/tiles:locateBatch", &reply, big)
          .ok());
  EXPECT_EQ(reply.status, 413u) << reply.body;
  EXPECT_THAT(reply.body, HasSubstr("--http-max-body-bytes"));
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
