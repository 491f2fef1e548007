// The router's inputs end to end: hostile grids and profiles get what a
// shard gives them, and points sent in another CRS are routed where PROJ
// puts them in the dataset's CRS, by the router and by clients routing
// themselves, answered and refused as one server serving the whole set. A
// shard answers the elevation APIs (which nobody routes) for every tile.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
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

namespace locator::test {
namespace {

// Whether the router's outcome of one request (its status, and its answer
// serialized) is the shard's: "" if so. Counts answers and refusals.
struct SameOutcome {
  std::string operator()(const std::string& request, const grpc::Status& got,
                         const std::string& got_answer,
                         const grpc::Status& want,
                         const std::string& want_answer) {
    if (got.error_code() != want.error_code()) {
      return request + ": " + got.error_message() + " / " +
             want.error_message();
    }
    ++(got.ok() ? answered : refused);
    if (got.ok() && got_answer != want_answer) return request + ": answers";
    return "";
  }
  int answered = 0, refused = 0;
};

// Hostile grids and profiles through the router: each gets what a shard
// called directly gives it (the same code and, when OK, the same answer),
// within its deadline, and the router keeps serving.
TEST_F(LocatordTileSetTest, TheRouterGivesHostileSurfacesAShardsAnswers) {
  const std::vector<std::string> limits = {"--max-grid-cells", "5000",
                                           "--max-profile-samples", "300"};
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter(limits, limits));
  auto routed = NewStub(*router_);
  auto direct = NewStub(*shard0_);

  SameOutcome grids;
  for (const v1::GridRequest& g : HostileGrids()) {
    v1::GridResponse via_router, from_shard;
    const grpc::Status got = StreamGrid(*routed, g, &via_router);
    const grpc::Status want = StreamGrid(*direct, g, &from_shard);
    EXPECT_EQ(grids(g.ShortDebugString().substr(0, 200), got,
                    via_router.SerializeAsString(), want,
                    from_shard.SerializeAsString()),
              "");
  }
  // Both kinds came: answers to compare, and refusals.
  EXPECT_GT(grids.answered, 10);
  EXPECT_GT(grids.refused, 10);

  SameOutcome profiles;
  for (const v1::ProfileRequest& p : HostileProfiles()) {
    const auto call = [&](v1::Locator::Stub& stub, v1::ProfileResponse* out) {
      grpc::ClientContext context;
      context.set_deadline(std::chrono::system_clock::now() +
                           std::chrono::seconds(30));
      return stub.Profile(&context, p, out);
    };
    v1::ProfileResponse via_router, from_shard;
    const grpc::Status got = call(*routed, &via_router);
    const grpc::Status want = call(*direct, &from_shard);
    EXPECT_EQ(
        profiles(p.ShortDebugString(), got, via_router.SerializeAsString(),
                 want, from_shard.SerializeAsString()),
        "");
  }
  EXPECT_GT(profiles.answered, 0);
  EXPECT_GT(profiles.refused, 10);

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

// A tile set in UTM zone 33N built in `dir` (a 2 km square near 15°E
// 49.6°N: 3,000 points valued 100 m rising 50 m eastwards, tiles of 400
// points); its directory, "" (and a test failure) if it was not built.
std::string BuildUtmTileSet(const std::string& dir) {
  const std::string csv = dir + "/utm.csv";
  {
    std::ofstream out(csv);
    out << "x,y,h\n";
    for (const Point2& p : GenerateUniform(3000, 5).points) {
      out << std::setprecision(12) << 500000 + 2000 * p.x << ","
          << 5500000 + 2000 * p.y << "," << 100 + 50 * p.x << "\n";
    }
  }
  const std::string tiles = dir + "/utm_tiles";
  const BinaryResult built =
      RunBinary(LOCATOR_BUILD_PATH,
                {"ogr:" + csv +
                     "?oo=X_POSSIBLE_NAMES=x&oo=Y_POSSIBLE_NAMES=y&z=h&a_srs="
                     "EPSG:32633",
                 "--out", tiles, "--tile-points", "400"});
  EXPECT_EQ(built.exit_code, 0) << built.err;
  return built.exit_code == 0 ? tiles : "";
}

// Lon/lat queries over the UTM tile set in `tiles` and around it: 1,000
// uniform ones and the seams between its tiles, mapped from UTM with PROJ;
// none (and a test failure) if PROJ fails.
std::vector<Point2> LonLatQueries(const std::string& tiles) {
  std::vector<Point2> queries;
  for (const Point2& p : GenerateUniform(1000, 8).points) {
    queries.push_back({499900 + 2200 * p.x, 5499900 + 2200 * p.y});
  }
  const std::vector<Point2> seams = TileSeamQueries(tiles);
  queries.insert(queries.end(), seams.begin(), seams.end());
  auto to_lon_lat = gis::CrsTransformer::Create("EPSG:4326", "EPSG:32633");
  EXPECT_TRUE(to_lon_lat.ok()) << to_lon_lat.status().message();
  if (!to_lon_lat.ok() || !(*to_lon_lat)->ToRequest(queries).ok()) return {};
  return queries;
}

// Points sent in another CRS are routed where they are in the dataset's
// CRS, as a shard transforms them: through the router, a tile set in UTM
// answers lon/lat batches and locates as one server serving it whole, seams
// included, and refuses what that server refuses with its words.
TEST_F(LocatordTileSetTest, TheRouterRoutesPointsSentInAnotherCrs) {
  tiles_ = BuildUtmTileSet(dir_.path());
  ASSERT_FALSE(tiles_.empty());
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter({}));
  std::unique_ptr<ServerProcess> whole;
  ASSERT_TRUE(
      StartLocatord("tiles=" + tiles_ + "/manifest.json", {}, &whole).ok());
  auto routed = NewStub(*router_);
  auto reference = NewStub(*whole);

  const std::vector<Point2> queries = LonLatQueries(tiles_);
  ASSERT_FALSE(queries.empty());

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

// The elevation APIs, which no client routes, are answered whole by any
// shard, as profiles, grids and terrain tiles are: Open Topo Data on one
// shard answers points of every tile as the whole set's server does.
TEST_F(LocatordTileSetTest, AShardAnswersTheElevationApisForEveryTile) {
  tiles_ = BuildUtmTileSet(dir_.path());
  ASSERT_FALSE(tiles_.empty());
  const std::string spec = "tiles=" + tiles_ + "/manifest.json";
  std::unique_ptr<ServerProcess> shard, whole;
  ASSERT_TRUE(StartLocatord(spec,
                            {"--tiles", "0/2", "--http-listen", "127.0.0.1:0"},
                            &shard)
                  .ok());
  ASSERT_TRUE(
      StartLocatord(spec, {"--http-listen", "127.0.0.1:0"}, &whole).ok());
  ASSERT_TRUE(shard->WaitForListening().ok());  // their HTTP lines
  ASSERT_TRUE(whole->WaitForListening().ok());
  const std::vector<Point2> queries = LonLatQueries(tiles_);
  ASSERT_GT(queries.size(), 200u);
  // 100 points a call (Open Topo Data's own limit).
  for (size_t first = 0; first + 100 <= 200; first += 100) {
    std::string path = "/opentopodata/v1/tiles?locations=";
    for (size_t i = first; i < first + 100; ++i) {
      std::ostringstream location;
      location << std::setprecision(17) << queries[i].y << "," << queries[i].x;
      path += (i == first ? "" : "|") + location.str();
    }
    HttpReply from_shard, from_whole;
    ASSERT_TRUE(SendHttp(shard->port(), "GET", path, &from_shard).ok());
    ASSERT_TRUE(SendHttp(whole->port(), "GET", path, &from_whole).ok());
    ASSERT_EQ(from_whole.status, 200u) << from_whole.body.substr(0, 300);
    EXPECT_EQ(from_shard.status, 200u) << from_shard.body.substr(0, 300);
    EXPECT_EQ(from_shard.body, from_whole.body);
  }
}

}  // namespace
}  // namespace locator::test
