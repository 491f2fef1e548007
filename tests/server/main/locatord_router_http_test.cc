// The router's HTTP/JSON API (locatord --route --http-listen) answers
// browsers and curl as the gRPC router does: :locate, :locateBatch,
// :profile, :grid (in one message, within --http-max-grid-cells) and
// :topology; other routes are 404 naming these, bad bodies 400, bodies
// past --http-max-body-bytes 413.

#include <gmock/gmock.h>
#include <google/protobuf/util/json_util.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/server/http/http_test_client.h"
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
  v1::GridRequest grid = GridAcrossTheTiles(40, 25);
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
