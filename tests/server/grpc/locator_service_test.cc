// LocatorService (over a LocatorApp) behind an in-process gRPC server, with an
// engine build held at a barrier: while a reload builds, GetStats reports it
// and a second Reload is refused; calls started before the swap finish on the
// engine they started with (a stream keeps it for its whole life), calls
// started after it use the new one.

#include "server/grpc/locator_service.h"

#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <future>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "locator/dataset_sources.h"
#include "tests/server/grpc/in_process_server.h"
#include "tests/server/main/e2e_support.h"

namespace locator {
namespace {

using Code = grpc::StatusCode;

std::shared_ptr<Engine> UniformEngine(size_t points, uint64_t seed) {
  StatusOr<std::unique_ptr<Engine>> engine =
      Engine::Create(GenerateUniform(points, seed), EngineOptions());
  EXPECT_TRUE(engine.ok()) << engine.status().ToString();
  return engine.ok() ? *std::move(engine) : nullptr;
}

// Whether `response` is `engine`'s own answer for `q`.
bool AnsweredBy(const Engine& engine, const Point2& q,
                const v1::LocateResponse& response) {
  LocateResult expected;
  if (!engine.Locate(q, &expected).ok()) return false;
  return response.triangle_id() == expected.triangle_id &&
         response.vertices_size() == 3 &&
         response.vertices(0).x() == expected.vertices[0].x &&
         response.vertices(0).y() == expected.vertices[0].y;
}

// Builds the next engine when Release() is called.
class HeldBuild {
 public:
  explicit HeldBuild(std::shared_ptr<Engine> next) : next_(std::move(next)) {}

  DatasetBuild Build() {
    return [this](const DatasetSlot&, const std::string&, Engine*,
                  BuiltDataset* built) {
      started_.set_value();
      released_.get_future().wait();
      built->engine = next_;
      return Status::OK();
    };
  }
  void WaitUntilStarted() { started_.get_future().wait(); }
  void Release() { released_.set_value(); }

 private:
  const std::shared_ptr<Engine> next_;
  std::promise<void> started_;
  std::promise<void> released_;
};

TEST(LocatorServiceTest, CallsInFlightFinishOnTheEngineTheyStartedWith) {
  const std::shared_ptr<Engine> old_engine = UniformEngine(2000, 1);
  const std::shared_ptr<Engine> new_engine = UniformEngine(3000, 2);
  HeldBuild held(new_engine);
  LocatorAppOptions options;
  options.build_engine = held.Build();
  LocatorApp app(options);
  LocatorService service(&app);
  DatasetSlot& dataset = app.datasets().default_slot();
  EXPECT_EQ(dataset.Publish({.engine = old_engine}), 1u);
  test::InProcessServer server(&service);
  auto stub = server.NewStub();

  const std::vector<Point2> queries = GenerateUniform(40, 9).points;
  grpc::ClientContext stream_context;
  auto stream = stub->LocateStream(&stream_context);
  size_t next = 0;
  // Round trips on the stream, each checked against `engine`.
  auto round_trips = [&](size_t count, const Engine& engine) {
    for (size_t k = 0; k < count; ++k, ++next) {
      const Point2& q = queries[next % queries.size()];
      v1::LocateResponse response;
      ASSERT_TRUE(stream->Write(test::LocateRequestFor(q)) &&
                  stream->Read(&response));
      EXPECT_TRUE(AnsweredBy(engine, q, response)) << "query " << next;
    }
  };
  round_trips(10, *old_engine);

  std::future<grpc::Status> reload = std::async(std::launch::async, [&] {
    grpc::ClientContext context;
    // The configured dataset, which every reload policy allows.
    v1::ReloadRequest request;
    v1::ReloadResponse response;
    grpc::Status status = stub->Reload(&context, request, &response);
    EXPECT_EQ(response.generation(), 2u);
    return status;
  });
  held.WaitUntilStarted();

  // While the build is held: reported, a second reload refused, the old
  // engine still answering every call.
  {
    grpc::ClientContext context;
    v1::GetStatsResponse stats;
    ASSERT_TRUE(stub->GetStats(&context, {}, &stats).ok());
    EXPECT_TRUE(stats.reload_in_progress());
    EXPECT_EQ(stats.generation(), 1u);
  }
  {
    grpc::ClientContext context;
    v1::ReloadResponse response;
    const grpc::Status refused = stub->Reload(&context, {}, &response);
    EXPECT_EQ(refused.error_code(), Code::FAILED_PRECONDITION);
    EXPECT_EQ(refused.error_message(), "reload in progress");
  }
  round_trips(10, *old_engine);
  {
    v1::LocateResponse response;
    ASSERT_TRUE(test::LocateOne(*stub, queries[0], &response).ok());
    EXPECT_TRUE(AnsweredBy(*old_engine, queries[0], response));
  }

  held.Release();
  const grpc::Status reloaded = reload.get();
  ASSERT_TRUE(reloaded.ok()) << reloaded.error_message();
  EXPECT_EQ(dataset.serving().engine, new_engine);

  // New calls use the new engine; the stream opened before keeps the old.
  {
    grpc::ClientContext context;
    v1::GetStatsResponse stats;
    ASSERT_TRUE(stub->GetStats(&context, {}, &stats).ok());
    EXPECT_FALSE(stats.reload_in_progress());
    EXPECT_EQ(stats.generation(), 2u);
  }
  for (const Point2& q : queries) {
    v1::LocateResponse response;
    ASSERT_TRUE(test::LocateOne(*stub, q, &response).ok());
    EXPECT_TRUE(AnsweredBy(*new_engine, q, response));
  }
  round_trips(20, *old_engine);
  stream->WritesDone();
  const grpc::Status stream_status = stream->Finish();
  EXPECT_TRUE(stream_status.ok()) << stream_status.error_message();
}

TEST(LocatorServiceTest, CallsBeforePublishAreRefusedAsLoading) {
  LocatorApp app(LocatorAppOptions{});
  LocatorService service(&app);
  test::InProcessServer server(&service);
  auto stub = server.NewStub();
  v1::LocateResponse response;
  const grpc::Status status = test::LocateOne(*stub, {0.5, 0.5}, &response);
  EXPECT_EQ(status.error_code(), Code::UNAVAILABLE);
  EXPECT_EQ(status.error_message(), "dataset 'default' is still loading");
}

TEST(LocatorServiceTest, DrainRefusesNewCalls) {
  LocatorApp app(LocatorAppOptions{});
  LocatorService service(&app);
  app.datasets().default_slot().Publish({.engine = UniformEngine(500, 3)});
  test::InProcessServer server(&service);
  auto stub = server.NewStub();
  app.Drain(std::chrono::system_clock::now());
  v1::LocateResponse response;
  const grpc::Status status = test::LocateOne(*stub, {0.5, 0.5}, &response);
  EXPECT_EQ(status.error_code(), Code::UNAVAILABLE);
  EXPECT_EQ(status.error_message(), "server is shutting down");
}

}  // namespace
}  // namespace locator
