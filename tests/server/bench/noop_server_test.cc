// locator-noop-server end to end: canned answers in the real message shapes,
// the NestedBatch comparison service, and an address in use.

#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>

#include "locator/bench/v1/nested_batch.grpc.pb.h"
#include "locator/v1/locator.grpc.pb.h"
#include "tests/testing/server_process.h"

namespace locator {
namespace {

using test::ServerProcess;

class NoopServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const Status started = ServerProcess::Start(
        NOOP_SERVER_PATH, {"--listen", "127.0.0.1:0"}, &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
    channel_ = grpc::CreateChannel(server_->target(),
                                   grpc::InsecureChannelCredentials());
  }

  std::unique_ptr<ServerProcess> server_;
  std::shared_ptr<grpc::Channel> channel_;
};

TEST_F(NoopServerTest, UnaryFillsEveryFieldOfTheFixedTriangle) {
  auto stub = v1::Locator::NewStub(channel_);
  grpc::ClientContext context;
  v1::LocateRequest request;
  request.mutable_point()->set_x(0.25);
  request.mutable_point()->set_y(0.5);
  v1::LocateResponse response;
  ASSERT_TRUE(stub->Locate(&context, request, &response).ok());
  EXPECT_EQ(response.type(), v1::LOCATION_TYPE_FACE);
  EXPECT_EQ(response.vertex_ids_size(), 3);
  EXPECT_EQ(response.vertices_size(), 3);
  ASSERT_EQ(response.barycentric_size(), 3);
  EXPECT_DOUBLE_EQ(response.barycentric(0), 0.25);
  EXPECT_TRUE(response.has_value());
  EXPECT_EQ(response.cost().total(), 1u);
}

TEST_F(NoopServerTest, BatchEchoesItsSize) {
  auto stub = v1::Locator::NewStub(channel_);
  v1::LocateBatchRequest request;
  for (int i = 0; i < 10'000; ++i) {
    request.add_xs(i * 1e-4);
    request.add_ys(0.5);
  }
  request.set_include_vertex_ids(true);
  grpc::ClientContext context;
  v1::LocateBatchResponse response;
  ASSERT_TRUE(stub->LocateBatch(&context, request, &response).ok());
  EXPECT_EQ(response.types_size(), 10'000);
  EXPECT_EQ(response.vertex_ids_size(), 30'000);
  EXPECT_EQ(response.total_cost(), 10'000u);
}

TEST_F(NoopServerTest, StreamAnswersEveryPoint) {
  auto stub = v1::Locator::NewStub(channel_);
  grpc::ClientContext context;
  auto stream = stub->LocateStream(&context);
  for (int i = 0; i < 10; ++i) {
    v1::LocateRequest request;
    request.mutable_point()->set_x(i);
    ASSERT_TRUE(stream->Write(request));
  }
  stream->WritesDone();
  int answers = 0;
  v1::LocateResponse response;
  while (stream->Read(&response)) ++answers;
  EXPECT_TRUE(stream->Finish().ok());
  EXPECT_EQ(answers, 10);
}

TEST_F(NoopServerTest, NestedBatchAnswersOneFilledResponsePerPoint) {
  auto stub = bench::v1::NestedBatch::NewStub(channel_);
  bench::v1::NestedBatchRequest request;
  for (int i = 0; i < 100; ++i) request.add_points()->set_x(i);
  grpc::ClientContext context;
  bench::v1::NestedBatchResponse response;
  ASSERT_TRUE(stub->LocateNested(&context, request, &response).ok());
  ASSERT_EQ(response.results_size(), 100);
  EXPECT_EQ(response.results(99).vertex_ids_size(), 3);
}

// It serves like locatord (see ServerRunner): a second server on the same
// port fails to start instead of sharing it.
TEST_F(NoopServerTest, AnAddressInUseExitsOne) {
  std::unique_ptr<ServerProcess> second;
  ASSERT_TRUE(ServerProcess::Spawn(NOOP_SERVER_PATH,
                                   {"--listen", server_->target()}, &second)
                  .ok());
  EXPECT_EQ(second->WaitForExit(std::chrono::seconds(30)), 1);
  EXPECT_NE(second->StderrText().find("cannot listen on " + server_->target()),
            std::string::npos)
      << second->StderrText();
}

}  // namespace
}  // namespace locator
