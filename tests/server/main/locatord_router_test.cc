// locatord --route end to end over two shards of a tile set: the router
// answers as the whole set does (CGAL's answers, seams included) for
// Locate, LocateBatch and LocateStream, forwards Profile and Grid to a shard
// and streams the grid back, passes hostile requests' refusals on as a
// shard gives them, reaches TLS shards with the --shard-tls flags, and
// answers over HTTP/JSON as over gRPC.

#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "client/locator_client.h"
#include "common/channel_options.h"
#include "common/gis/crs_transformer.h"
#include "locator/dataset_sources.h"
#include "tests/server/http/http_test_client.h"
#include "tests/server/main/e2e_support.h"
#include "tests/server/main/tile_set_fixture.h"
#include "tests/testing/run_binary.h"
#include "tests/testing/test_pki.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

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

// A LocateStream through the router: each point goes to its shard, several
// in flight, and the answers come back in the order of the points; a bad
// point ends the stream after the answers before it; callers that go away
// leave the router serving.
TEST_F(LocatordTileSetTest, TheRouterStreamsEachPointToItsShardInOrder) {
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter({}));
  auto stub = NewStub(*router_);
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(csv_, &reference).ok());
  std::vector<Point2> queries = TestQueries();
  const std::vector<Point2> seams = TileSeamQueries(tiles_);
  queries.insert(queries.end(), seams.begin(), seams.end());
  const std::vector<LocateResult> answers = LocateOverStream(*stub, queries);
  ASSERT_EQ(answers.size(), queries.size());
  EXPECT_EQ(reference->Disagreements(queries, answers, false), "");

  // A shard's refusal ends the stream as a server's would, after the
  // answers to the points before it.
  const auto answered_before_refusal = [&](std::span<const Point2> points,
                                           grpc::Status* status) {
    size_t answered = 0;
    *status = StreamPoints(*stub, points,
                           [&](const v1::LocateResponse&) { ++answered; });
    return answered;
  };
  std::vector<Point2> bad(std::min<size_t>(queries.size(), 600));
  std::copy_n(queries.begin(), bad.size(), bad.begin());
  bad[400] = {std::numeric_limits<double>::quiet_NaN(), 0.5};
  grpc::Status status;
  EXPECT_EQ(answered_before_refusal(bad, &status), 400u);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  bad[400] = {1e300, -1e300};  // outside every tile
  bad[200] = {0.5, std::numeric_limits<double>::infinity()};
  EXPECT_EQ(answered_before_refusal(bad, &status), 200u);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);

  // Callers that stop reading and cancel leave the router serving.
  for (int call = 0; call < 3; ++call) {
    grpc::ClientContext cancelled;
    auto stream = stub->LocateStream(&cancelled);
    for (int i = 0; i < 200; ++i) {
      if (!stream->Write(LocateRequestFor(queries[i]))) break;
    }
    v1::LocateResponse first;
    ASSERT_TRUE(stream->Read(&first));
    cancelled.TryCancel();
    EXPECT_EQ(stream->Finish().error_code(), grpc::StatusCode::CANCELLED);
  }
  const std::span<const Point2> some(queries.data(), 100);
  EXPECT_EQ(
      reference->Disagreements(some, LocateOverStream(*stub, some), false), "");
}

// Hostile grids and profiles through the router: each gets what a shard
// called directly gives it (the same code and, when OK, the same answer),
// within its deadline, and the router keeps serving.
TEST_F(LocatordTileSetTest, TheRouterGivesHostileSurfacesAShardsAnswers) {
  const std::vector<std::string> limits = {"--max-grid-cells", "5000",
                                           "--max-profile-samples", "300"};
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter(limits, limits));
  auto routed = NewStub(*router_);
  auto direct = NewStub(*shard0_);
  const double kNaN = std::numeric_limits<double>::quiet_NaN();
  const double kInf = std::numeric_limits<double>::infinity();
  const std::vector<double> hostile = {
      kNaN,   kInf,     -kInf, 1e300,
      -1e300, 4.9e-324, -0.0,  std::numeric_limits<double>::max()};

  v1::GridRequest benign;
  benign.mutable_box()->set_min_x(0.1);
  benign.mutable_box()->set_min_y(0.2);
  benign.mutable_box()->set_max_x(0.9);
  benign.mutable_box()->set_max_y(0.7);
  benign.set_width(5);
  benign.set_height(4);
  std::vector<v1::GridRequest> grids;
  for (const double v : hostile) {
    for (int field = 0; field < 6; ++field) {
      v1::GridRequest g = benign;
      v1::BoundingBox& box = *g.mutable_box();
      switch (field) {
        case 0:
          box.set_min_x(v);
          break;
        case 1:
          box.set_min_y(v);
          break;
        case 2:
          box.set_max_x(v);
          break;
        case 3:
          box.set_max_y(v);
          break;
        case 4:
          g.set_nodata(v);
          break;
        case 5:
          g.clear_width(), g.clear_height(), g.set_cell_size(v);
          break;
      }
      grids.push_back(g);
    }
  }
  for (const auto& [width, height] : {std::pair<uint32_t, uint32_t>{0, 4},
                                      {5, 0},
                                      {5000, 2},
                                      {4294967295u, 4294967295u}}) {
    v1::GridRequest g = benign;
    g.set_width(width);
    g.set_height(height);
    grids.push_back(g);
  }
  grids.push_back(benign);
  grids.back().set_interpolation(static_cast<v1::Interpolation>(99));
  grids.push_back(benign);
  grids.back().set_dataset(std::string(100000, 'x'));
  // Both kinds come: answers to compare, and refusals.
  int answered = 0, refused = 0;
  for (const v1::GridRequest& g : grids) {
    v1::GridResponse via_router, from_shard;
    const grpc::Status status = StreamGrid(*routed, g, &via_router);
    const grpc::Status want = StreamGrid(*direct, g, &from_shard);
    const std::string request = g.ShortDebugString().substr(0, 200);
    EXPECT_EQ(status.error_code(), want.error_code())
        << request << ": " << status.error_message() << " / "
        << want.error_message();
    if (!status.ok() || !want.ok()) {
      ++refused;
      continue;
    }
    ++answered;
    EXPECT_EQ(via_router.SerializeAsString(), from_shard.SerializeAsString())
        << request;
  }
  EXPECT_GT(answered, 10);
  EXPECT_GT(refused, 10);

  v1::ProfileRequest line;
  for (const Point2& p : {Point2{0.1, 0.1}, Point2{0.9, 0.8}}) {
    v1::Point* vertex = line.add_vertices();
    vertex->set_x(p.x);
    vertex->set_y(p.y);
  }
  std::vector<v1::ProfileRequest> profiles;
  for (const double v : hostile) {
    for (int field = 0; field < 4; ++field) {
      v1::ProfileRequest p = line;
      v1::Point& vertex = *p.mutable_vertices(field / 2);
      field % 2 == 0 ? vertex.set_x(v) : vertex.set_y(v);
      profiles.push_back(p);
    }
  }
  for (const uint32_t samples : {1u, 301u, 4294967295u}) {
    profiles.push_back(line);
    profiles.back().set_samples(samples);
  }
  profiles.push_back(v1::ProfileRequest());  // no vertices
  for (const v1::ProfileRequest& p : profiles) {
    const auto call = [&](v1::Locator::Stub& stub, v1::ProfileResponse* out) {
      grpc::ClientContext context;
      context.set_deadline(std::chrono::system_clock::now() +
                           std::chrono::seconds(30));
      return stub.Profile(&context, p, out);
    };
    v1::ProfileResponse via_router, from_shard;
    const grpc::Status status = call(*routed, &via_router);
    const grpc::Status want = call(*direct, &from_shard);
    EXPECT_EQ(status.error_code(), want.error_code())
        << p.ShortDebugString() << ": " << status.error_message() << " / "
        << want.error_message();
    if (!status.ok() || !want.ok()) continue;
    EXPECT_EQ(via_router.SerializeAsString(), from_shard.SerializeAsString())
        << p.ShortDebugString();
  }

  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(csv_, &reference).ok());
  const std::vector<Point2> control = {{0.5, 0.5}, {0.25, 0.75}};
  EXPECT_EQ(
      reference->Disagreements(control, LocateEach(*routed, control), false),
      "");
}

// "" when `got` and `want`, two answers for the same point, agree: the same
// kind of location and the same triangle, or for a point on an edge (a
// vertex) triangles sharing it, which any walk may name; the same value.
std::string Disagreement(const LocateResult& got, const LocateResult& want) {
  if (got.type != want.type) return "another type";
  int shared = 0;
  for (const int64_t v : got.vertex_ids) {
    shared += std::count(want.vertex_ids.begin(), want.vertex_ids.end(), v);
  }
  const bool degenerate =
      got.type == LocationType::kEdge || got.type == LocationType::kVertex;
  if (!degenerate && got.triangle_id != want.triangle_id) {
    return "triangle " + std::to_string(got.triangle_id) + ", not " +
           std::to_string(want.triangle_id);
  }
  if (degenerate && shared < (got.type == LocationType::kVertex ? 1 : 2)) {
    return "no shared edge or vertex";
  }
  if (got.has_value != want.has_value) return "a value where none is due";
  if (got.has_value && !(std::abs(got.value - want.value) <=
                         1e-9 * (1 + std::abs(want.value)))) {
    return "value " + std::to_string(got.value);
  }
  return "";
}

// Points sent in another CRS are routed where they are in the dataset's
// CRS, as a shard transforms them: through the router, a tile set in UTM
// answers lon/lat batches and locates as one server serving it whole, seams
// included, and refuses what that server refuses with its words.
TEST_F(LocatordTileSetTest, TheRouterRoutesPointsSentInAnotherCrs) {
  // The tile set, in UTM zone 33N: a 2 km square near 15°E 49.6°N.
  const std::string csv = dir_.path() + "/utm.csv";
  {
    std::ofstream out(csv);
    out << "x,y,h\n";
    for (const Point2& p : GenerateUniform(3000, 5).points) {
      out << std::setprecision(12) << 500000 + 2000 * p.x << ","
          << 5500000 + 2000 * p.y << "," << 100 + 50 * p.x << "\n";
    }
  }
  tiles_ = dir_.path() + "/utm_tiles";
  const BinaryResult built =
      RunBinary(LOCATOR_BUILD_PATH,
                {"ogr:" + csv +
                     "?oo=X_POSSIBLE_NAMES=x&oo=Y_POSSIBLE_NAMES=y&z=h&a_srs="
                     "EPSG:32633",
                 "--out", tiles_, "--tile-points", "400"});
  ASSERT_EQ(built.exit_code, 0) << built.err;
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter({}));
  std::unique_ptr<ServerProcess> whole;
  ASSERT_TRUE(
      StartLocatord("tiles=" + tiles_ + "/manifest.json", {}, &whole).ok());
  auto routed = NewStub(*router_);
  auto reference = NewStub(*whole);

  // Lon/lat queries: uniform ones and the seams between tiles, mapped from
  // UTM with PROJ.
  std::vector<Point2> queries;
  for (const Point2& p : GenerateUniform(1000, 8).points) {
    queries.push_back({499900 + 2200 * p.x, 5499900 + 2200 * p.y});
  }
  const std::vector<Point2> seams = TileSeamQueries(tiles_);
  queries.insert(queries.end(), seams.begin(), seams.end());
  auto to_lon_lat = gis::CrsTransformer::Create("EPSG:4326", "EPSG:32633");
  ASSERT_TRUE(to_lon_lat.ok()) << to_lon_lat.status().message();
  ASSERT_TRUE((*to_lon_lat)->ToRequest(queries).ok());

  const auto batch = [&](v1::Locator::Stub& stub,
                         const v1::LocateBatchRequest& request,
                         v1::LocateBatchResponse* response) {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() +
                         std::chrono::seconds(30));
    return stub.LocateBatch(&context, request, response);
  };
  v1::LocateBatchRequest request = BatchRequestFor(queries);
  request.set_crs("EPSG:4326");
  v1::LocateBatchResponse via_router, from_whole;
  ASSERT_TRUE(batch(*routed, request, &via_router).ok());
  ASSERT_TRUE(batch(*reference, request, &from_whole).ok());
  ASSERT_EQ(via_router.types_size(), static_cast<int>(queries.size()));
  for (size_t i = 0; i < queries.size(); ++i) {
    ASSERT_EQ(
        Disagreement(FromBatchRow(via_router, i), FromBatchRow(from_whole, i)),
        "")
        << "point " << i;
  }
  for (size_t i = 0; i < 50; ++i) {
    v1::LocateRequest one = LocateRequestFor(queries[i * 7]);
    one.set_crs("EPSG:4326");
    one.set_vertices_in_request_crs(true);
    v1::LocateResponse got, want;
    grpc::ClientContext context, reference_context;
    ASSERT_TRUE(routed->Locate(&context, one, &got).ok());
    ASSERT_TRUE(reference->Locate(&reference_context, one, &want).ok());
    EXPECT_EQ(got.triangle_id(), want.triangle_id());
    EXPECT_EQ(got.vertices(0).SerializeAsString(),
              want.vertices(0).SerializeAsString());
  }

  // A client routing by the topology itself maps the points as the router
  // does.
  RequestScope scope;
  scope.crs = "EPSG:4326";
  const ChannelOptions to_router{.target = router_->target()};
  LocatorClient client(CreateLocatorChannel(to_router),
                       std::chrono::seconds(30), scope);
  ASSERT_TRUE(client.RouteByTopology(to_router).ok());
  std::vector<double> xs, ys;
  for (const Point2& q : queries) {
    xs.push_back(q.x);
    ys.push_back(q.y);
  }
  v1::LocateBatchResponse by_client;
  ASSERT_TRUE(client
                  .LocateBatch(
                      xs, ys,
                      {.vertex_ids = true, .barycentric = true, .values = true},
                      &by_client)
                  .ok());
  ASSERT_EQ(by_client.triangle_ids_size(), from_whole.triangle_ids_size());
  for (size_t i = 0; i < queries.size(); ++i) {
    ASSERT_EQ(
        Disagreement(FromBatchRow(by_client, i), FromBatchRow(from_whole, i)),
        "")
        << "point " << i;
  }
  for (size_t i = 0; i < queries.size(); i += 97) {
    v1::LocateResponse one;
    ASSERT_TRUE(client.Locate(queries[i], &one).ok()) << i;
    EXPECT_EQ(
        Disagreement(FromLocateResponse(one), FromBatchRow(from_whole, i)), "")
        << "point " << i;
  }

  // Refused as the whole set's server refuses them: a point outside the
  // CRS's area of use, an unknown CRS, one that names a file.
  for (const auto& [crs, far] : {std::pair{"EPSG:4326", Point2{170, -80}},
                                 std::pair{"EPSG:999999", Point2{15, 49.6}},
                                 std::pair{"/etc/passwd", Point2{15, 49.6}}}) {
    std::vector<Point2> points(queries.begin(), queries.begin() + 20);
    points[13] = far;
    v1::LocateBatchRequest refused = BatchRequestFor(points);
    refused.set_crs(crs);
    const grpc::Status status = batch(*routed, refused, &via_router);
    const grpc::Status want = batch(*reference, refused, &from_whole);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << crs;
    EXPECT_EQ(status.error_code(), want.error_code()) << crs;
    EXPECT_EQ(status.error_message(), want.error_message()) << crs;
    v1::LocateRequest one = LocateRequestFor(far);
    one.set_crs(crs);
    v1::LocateResponse unused;
    grpc::ClientContext context, reference_context;
    const grpc::Status located = routed->Locate(&context, one, &unused);
    const grpc::Status wanted =
        reference->Locate(&reference_context, one, &unused);
    EXPECT_EQ(located.error_code(), wanted.error_code()) << crs;
    EXPECT_EQ(located.error_message(), wanted.error_message()) << crs;
  }
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
      {"--http-listen", "127.0.0.1:0", "--http-max-body-bytes", "4096",
       "--http-max-grid-cells", "1000"}));
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
  // A profile across the tiles, as a shard answers it over gRPC.
  v1::ProfileRequest line;
  line.set_dataset("tiles");
  for (const Point2& p : {Point2{0.05, 0.1}, Point2{0.95, 0.9}}) {
    v1::Point* vertex = line.add_vertices();
    vertex->set_x(p.x);
    vertex->set_y(p.y);
  }
  v1::ProfileResponse over_grpc_profile;
  grpc::ClientContext profile_context;
  ASSERT_TRUE(NewStub(*shard0_)
                  ->Profile(&profile_context, line, &over_grpc_profile)
                  .ok());
  ASSERT_GT(over_grpc_profile.breakpoints_size(), 10);
  line.clear_dataset();
  std::string profile_body;
  ASSERT_TRUE(
      google::protobuf::util::MessageToJsonString(line, &profile_body).ok());
  ASSERT_TRUE(SendHttp(http_port, "POST", "/v1/datasets/tiles:profile", &reply,
                       profile_body)
                  .ok());
  ASSERT_EQ(reply.status, 200u) << reply.body;
  v1::ProfileResponse over_http_profile;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(reply.body,
                                                          &over_http_profile)
                  .ok());
  EXPECT_EQ(over_http_profile.SerializeAsString(),
            over_grpc_profile.SerializeAsString());
  ASSERT_TRUE(SendHttp(http_port, "POST", "/v1/datasets/tiles:profile", &reply,
                       "{\"vertices\": [{\"x\": 1e999, \"y\": 0}]}")
                  .ok());
  EXPECT_EQ(reply.status, 400u) << reply.body;

  // A grid in one JSON answer, as a shard streams it over gRPC; one past
  // the router's --http-max-grid-cells is refused naming it.
  v1::GridRequest grid;
  grid.set_dataset("tiles");
  grid.mutable_box()->set_min_x(-0.1);
  grid.mutable_box()->set_min_y(0.05);
  grid.mutable_box()->set_max_x(1.1);
  grid.mutable_box()->set_max_y(0.95);
  grid.set_width(40);
  grid.set_height(25);
  grid.set_nodata(-1);
  v1::GridResponse streamed;
  ASSERT_TRUE(StreamGrid(*NewStub(*shard1_), grid, &streamed).ok());
  grid.clear_dataset();
  std::string grid_body;
  ASSERT_TRUE(
      google::protobuf::util::MessageToJsonString(grid, &grid_body).ok());
  ASSERT_TRUE(
      SendHttp(http_port, "POST", "/v1/datasets/tiles:grid", &reply, grid_body)
          .ok());
  ASSERT_EQ(reply.status, 200u) << reply.body.substr(0, 300);
  v1::GridResponse over_http_grid;
  ASSERT_TRUE(
      google::protobuf::util::JsonStringToMessage(reply.body, &over_http_grid)
          .ok());
  EXPECT_EQ(over_http_grid.header().SerializeAsString(),
            streamed.header().SerializeAsString());
  EXPECT_EQ(over_http_grid.rows(), 25u);
  ASSERT_EQ(over_http_grid.values_size(), 40 * 25);
  for (int v = 0; v < over_http_grid.values_size(); ++v) {
    // A cell on an edge may take its value from either face.
    ASSERT_NEAR(over_http_grid.values(v), streamed.values(v), 1e-9) << v;
  }
  grid.set_height(26);
  grid_body.clear();
  ASSERT_TRUE(
      google::protobuf::util::MessageToJsonString(grid, &grid_body).ok());
  ASSERT_TRUE(
      SendHttp(http_port, "POST", "/v1/datasets/tiles:grid", &reply, grid_body)
          .ok());
  EXPECT_EQ(reply.status, 429u) << reply.body;
  EXPECT_THAT(reply.body, HasSubstr("--http-max-grid-cells"));

  // A shard's own routes are not the router's; bad bodies are 400.
  ASSERT_TRUE(
      SendHttp(http_port, "GET", "/v1/datasets/tiles/tiles/0/0/0.png", &reply)
          .ok());
  EXPECT_EQ(reply.status, 404u);
  EXPECT_THAT(reply.body,
              HasSubstr("tiles and the elevation APIs are a shard's"));
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

}  // namespace
}  // namespace locator::test
