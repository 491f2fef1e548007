// The router's HTTP/JSON API (locatord --route --http-listen) answers
// browsers and curl as the gRPC router does: :locate, :locateBatch,
// :profile, :grid (in one message, within --http-max-grid-cells) and
// :topology, and /metrics counts its gRPC calls; other routes are 404 naming
// these, bad bodies 400, bodies past --http-max-body-bytes 413, POSTs that are
// not JSON 415; hostile grids, profiles and bodies get what a shard's HTTP API
// gives them.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/server/http/http_test_client.h"
#include "tests/server/http/json_api_support.h"
#include "tests/server/main/e2e_support.h"
#include "tests/server/main/tile_set_fixture.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

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
  HttpReply reply =
      Post(http_port, "/v1/datasets/tiles:locateBatch", ToJson(request));
  ASSERT_EQ(reply.status, 200u) << reply.body;
  const auto over_http = FromJson<v1::LocateBatchResponse>(reply.body);
  EXPECT_EQ(over_http.triangle_ids_size(), 5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(over_http.triangle_ids(i), over_grpc.triangle_ids(i)) << i;
    EXPECT_EQ(over_http.types(i), over_grpc.types(i)) << i;
  }
  ASSERT_TRUE(
      SendHttp(http_port, "GET", "/v1/datasets/tiles:topology", &reply).ok());
  EXPECT_EQ(reply.status, 200u);
  EXPECT_THAT(reply.body, HasSubstr("\"complete\":true"));
  // Its /metrics counts its gRPC calls (recorded before their status is
  // sent), as locatord's does.
  ASSERT_TRUE(HttpGet(http_port, "/metrics", &reply).ok());
  EXPECT_EQ(reply.status, 200u);
  EXPECT_THAT(reply.headers["content-type"], HasSubstr("version=0.0.4"));
  EXPECT_THAT(reply.body,
              HasSubstr("locator_rpc_requests_total{code=\"OK\",method="
                        "\"LocateBatch\",service=\"locator.v1.Locator\"} 1"));
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
  reply = Post(http_port, "/v1/datasets/tiles:profile", ToJson(line));
  ASSERT_EQ(reply.status, 200u) << reply.body;
  const auto over_http_profile = FromJson<v1::ProfileResponse>(reply.body);
  EXPECT_EQ(over_http_profile.SerializeAsString(),
            over_grpc_profile.SerializeAsString());
  reply = Post(http_port, "/v1/datasets/tiles:profile",
               "{\"vertices\": [{\"x\": 1e999, \"y\": 0}]}");
  EXPECT_EQ(reply.status, 400u) << reply.body;

  // A grid in one JSON answer, as a shard streams it over gRPC; one past
  // the router's --http-max-grid-cells is refused naming it.
  v1::GridRequest grid = GridAcrossTheTiles(40, 25);
  v1::GridResponse streamed;
  ASSERT_TRUE(StreamGrid(*NewStub(*shard1_), grid, &streamed).ok());
  grid.clear_dataset();
  reply = Post(http_port, "/v1/datasets/tiles:grid", ToJson(grid));
  ASSERT_EQ(reply.status, 200u) << reply.body.substr(0, 300);
  const auto over_http_grid = FromJson<v1::GridResponse>(reply.body);
  EXPECT_EQ(over_http_grid.header().SerializeAsString(),
            streamed.header().SerializeAsString());
  EXPECT_EQ(over_http_grid.rows(), 25u);
  ASSERT_EQ(over_http_grid.values_size(), 40 * 25);
  for (int v = 0; v < over_http_grid.values_size(); ++v) {
    // A cell on an edge may take its value from either face.
    ASSERT_NEAR(over_http_grid.values(v), streamed.values(v), 1e-9) << v;
  }
  grid.set_height(26);
  reply = Post(http_port, "/v1/datasets/tiles:grid", ToJson(grid));
  EXPECT_EQ(reply.status, 429u) << reply.body;
  EXPECT_THAT(reply.body, HasSubstr("--http-max-grid-cells"));

  // A shard's own routes are not the router's; bad bodies are 400.
  ASSERT_TRUE(
      SendHttp(http_port, "GET", "/v1/datasets/tiles/tiles/0/0/0.png", &reply)
          .ok());
  EXPECT_EQ(reply.status, 404u);
  EXPECT_THAT(reply.body,
              HasSubstr("tiles and the elevation APIs are a shard's"));
  reply = Post(http_port, "/v1/datasets/tiles:locate",
               "{\"point\": {\"x\": \"NaN\", \"y\": 1}}");
  EXPECT_EQ(reply.status, 400u) << reply.body;
  reply = Post(http_port, "/v1/datasets/tiles:locate", "{\"pont\": 1}");
  EXPECT_EQ(reply.status, 400u) << reply.body;
  // A POST that does not say it is JSON is refused, as a shard refuses it:
  // a page of another origin can send a text/plain one without a CORS
  // preflight.
  ASSERT_TRUE(SendHttp(http_port, "POST", "/v1/datasets/tiles:locate", &reply,
                       "{\"point\": {\"x\": 0.5, \"y\": 0.5}}")
                  .ok());
  EXPECT_EQ(reply.status, 415u) << reply.body;
  reply = Post(http_port, "/v1/datasets/tiles:locate",
               "{\"point\": {\"x\": \"Infinity\", \"y\": 1}}");
  EXPECT_EQ(reply.status, 400u) << reply.body;
  // A body past --http-max-body-bytes is refused before it is read whole.
  const std::string big = "{\"xs\": [" + std::string(5000, ' ') + "]}";
  reply = Post(http_port, "/v1/datasets/tiles:locateBatch", big);
  EXPECT_EQ(reply.status, 413u) << reply.body;
  EXPECT_THAT(reply.body, HasSubstr("--http-max-body-bytes"));
}

// The JSON body of `request` for the HTTP API, whose path names the
// dataset: the dataset field cleared.
template <typename Request>
std::string JsonBodyOf(Request request) {
  request.clear_dataset();
  return ToJson(request);
}

// Compares the router's HTTP answers to hostile requests with a shard's
// (over HTTP too): the same status, and on 200 answers that `same` finds
// equal. Counts answers and refusals.
class SameHttpOutcome {
 public:
  SameHttpOutcome(int router_port, int shard_port)
      : router_port_(router_port), shard_port_(shard_port) {}

  // "" when both answer `body` POSTed to `target` alike, else what
  // differs.
  template <typename Same>
  std::string operator()(const std::string& target, const std::string& body,
                         Same same) {
    HttpReply got, want;
    const HttpHeaders json = {{"Content-Type", "application/json"}};
    const Status sent =
        SendHttp(router_port_, "POST", target, &got, body, json);
    const Status sent_to_shard =
        SendHttp(shard_port_, "POST", target, &want, body, json);
    const std::string request =
        target.substr(0, 80) + " " + body.substr(0, 160);
    if (!sent.ok() || !sent_to_shard.ok()) {
      return request + ": " + sent.message() + " / " + sent_to_shard.message();
    }
    if (got.status != want.status) {
      return request + ": " + std::to_string(got.status) + " " +
             got.body.substr(0, 200) + " / " + std::to_string(want.status) +
             " " + want.body.substr(0, 200);
    }
    ++(got.status == 200 ? answered : refused);
    if (got.status == 200 && !same(got, want)) return request + ": answers";
    return "";
  }

  int answered = 0, refused = 0;

 private:
  const int router_port_, shard_port_;
};

// Hostile grids and profiles through the router's HTTP API get what a
// shard's HTTP API gives them (the same status and, on 200, the same
// answer), as do hostile JSON bodies, and the router keeps serving.
TEST_F(LocatordTileSetTest,
       TheRouterGivesHostileSurfacesOverHttpAShardsAnswers) {
  const std::vector<std::string> flags = {
      "--http-listen",         "127.0.0.1:0", "--max-grid-cells",      "5000",
      "--http-max-grid-cells", "5000",        "--max-profile-samples", "300"};
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter(flags, flags));
  auto routed = NewStub(*router_);
  // Their HTTP lines, after the gRPC ones.
  ASSERT_TRUE(router_->WaitForListening().ok());
  ASSERT_TRUE(shard0_->WaitForListening().ok());
  SameHttpOutcome outcome(router_->port(), shard0_->port());

  const auto same_grid = [](const HttpReply& got, const HttpReply& want) {
    const auto a = FromJson<v1::GridResponse>(got.body);
    const auto b = FromJson<v1::GridResponse>(want.body);
    if (a.header().SerializeAsString() != b.header().SerializeAsString() ||
        a.values_size() != b.values_size()) {
      return false;
    }
    for (int v = 0; v < a.values_size(); ++v) {
      // A cell on an edge may take its value from either face; nodata
      // may be NaN.
      const bool both_nan = std::isnan(a.values(v)) && std::isnan(b.values(v));
      if (!both_nan && !(std::abs(a.values(v) - b.values(v)) <= 1e-9) &&
          a.values(v) != b.values(v)) {
        return false;
      }
    }
    return true;
  };
  for (const v1::GridRequest& g : HostileGrids()) {
    const std::string dataset = g.dataset().empty() ? "tiles" : g.dataset();
    EXPECT_EQ(
        outcome("/v1/datasets/" + dataset + ":grid", JsonBodyOf(g), same_grid),
        "");
  }
  const auto same_profile = [](const HttpReply& got, const HttpReply& want) {
    return FromJson<v1::ProfileResponse>(got.body).SerializeAsString() ==
           FromJson<v1::ProfileResponse>(want.body).SerializeAsString();
  };
  for (const v1::ProfileRequest& p : HostileProfiles()) {
    EXPECT_EQ(
        outcome("/v1/datasets/tiles:profile", JsonBodyOf(p), same_profile), "");
  }
  // JSON that is no request, or numbers protobuf's JSON cannot hold.
  for (const std::string& body :
       {std::string(), std::string("{"), std::string("[]"), std::string("null"),
        std::string("{\"box\": \"x\"}"),
        std::string("{\"width\": 1e400, \"height\": 2}"),
        std::string("{\"width\": -1, \"height\": 2}"),
        std::string("{\"cellSize\": \"-Infinity\"}"),
        std::string("{\"samples\": 18446744073709551616}"),
        std::string("{\"vertices\": [{\"x\": \"NaN\", \"y\": 0}, {}]}"),
        std::string("{\"vertices\": 7}"), std::string(3000, '[')}) {
    EXPECT_EQ(outcome("/v1/datasets/tiles:grid", body, same_grid), "");
    EXPECT_EQ(outcome("/v1/datasets/tiles:profile", body, same_profile), "");
  }
  // Both kinds came: answers to compare, and refusals.
  EXPECT_GT(outcome.answered, 10);
  EXPECT_GT(outcome.refused, 40);

  // Still serving (a failed call is a test failure).
  const std::vector<Point2> control = {{0.5, 0.5}, {0.25, 0.75}};
  EXPECT_EQ(LocateEach(*routed, control).size(), 2u);
}

}  // namespace
}  // namespace locator::test
