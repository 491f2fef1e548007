// locatord --route end to end over two shards of a tile set: the router
// answers as the whole set does (CGAL's answers, seams included) for
// Locate, LocateBatch and LocateStream, forwards Profile and Grid to a shard
// and streams the grid back, and reaches TLS shards with the --shard-tls
// flags. Hostile and CRS requests: locatord_router_input_test.cc; HTTP:
// locatord_router_http_test.cc.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tests/server/main/e2e_support.h"
#include "tests/server/main/tile_set_fixture.h"
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
  v1::GridRequest grid = GridAcrossTheTiles(300, 700);
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

// Each stream through the router reaches a shard on a stream of its own:
// a shard that dies under it fails the points it had not answered, naming
// the shard, and the client's stream ends with that status rather than
// waiting; the router goes on serving the other shard's points.
TEST_F(LocatordTileSetTest, AStreamThroughTheRouterEndsWhenItsShardDies) {
  ASSERT_NO_FATAL_FAILURE(StartShardsAndRouter({}));
  auto stub = NewStub(*router_);
  const std::vector<Point2> queries = TestQueries();
  ASSERT_GE(queries.size(), 200u);
  ASSERT_EQ(LocateOverStream(*stub, queries).size(), queries.size());

  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() +
                       std::chrono::seconds(30));
  auto stream = stub->LocateStream(&context);
  for (size_t i = 0; i < 50; ++i) {
    ASSERT_TRUE(stream->Write(LocateRequestFor(queries[i])));
  }
  v1::LocateResponse answer;
  ASSERT_TRUE(stream->Read(&answer));
  shard1_->SendSignal(SIGKILL);
  // Points of both shards after the kill: shard 1's cannot be answered.
  for (size_t i = 50; i < 200; ++i) {
    if (!stream->Write(LocateRequestFor(queries[i]))) break;
  }
  stream->WritesDone();
  size_t answered = 1;
  while (stream->Read(&answer)) ++answered;
  const grpc::Status ended = stream->Finish();
  EXPECT_LT(answered, 200u);
  EXPECT_EQ(ended.error_code(), grpc::StatusCode::UNAVAILABLE)
      << ended.error_message();
  EXPECT_THAT(ended.error_message(), HasSubstr("shard 1 ("));

  // Shard 0's points are still answered, shard 1's refused naming it (each
  // after the channel's retries of UNAVAILABLE: one of each is enough).
  int located = 0, refused = 0;
  for (size_t i = 0; i < queries.size() && (located == 0 || refused == 0);
       ++i) {
    grpc::ClientContext one;
    one.set_deadline(std::chrono::system_clock::now() +
                     std::chrono::seconds(10));
    v1::LocateResponse response;
    const grpc::Status status =
        stub->Locate(&one, LocateRequestFor(queries[i]), &response);
    if (status.ok()) {
      ++located;
    } else {
      ++refused;
      EXPECT_THAT(status.error_message(), HasSubstr("shard 1 (")) << i;
    }
  }
  EXPECT_GT(located, 0);
  EXPECT_GT(refused, 0);
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

}  // namespace
}  // namespace locator::test
