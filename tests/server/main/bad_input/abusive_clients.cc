#include "tests/server/main/bad_input/abusive_clients.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "tests/server/main/e2e_support.h"
#include "tests/testing/process_memory.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

// Far more than flow control lets through: if the writers got to the end,
// the server read (and buffered) everything.
constexpr uint64_t kFloodPoints = 2'000'000;

// Under ASAN freed memory stays resident in its quarantine (256 MiB by
// default), and TSAN's allocator and shadow memory keep what they touched,
// so a sanitized server's RSS says nothing about what it buffers; the plain
// build checks the bound. The build defines LOCATOR_SANITIZED_SERVER when
// locatord is built with a sanitizer (tests/server/CMakeLists.txt).
#if defined(LOCATOR_SANITIZED_SERVER)
constexpr bool kRssShowsBuffering = false;
#else
constexpr bool kRssShowsBuffering = true;
#endif

// One stream of the flood and the thread writing to it.
struct FloodStream {
  grpc::ClientContext context;
  std::unique_ptr<
      grpc::ClientReaderWriter<v1::LocateRequest, v1::LocateResponse>>
      stream;
  std::atomic<uint64_t> written{0};
  std::thread writer;
};

uint64_t TotalWritten(const std::vector<std::unique_ptr<FloodStream>>& floods) {
  uint64_t total = 0;
  for (const auto& flood : floods) total += flood->written.load();
  return total;
}

// Waits until neither the writers nor the server make progress any more
// (flow control holds the writers and the server reads no further), or the
// writers have all finished. Progress is the points written plus the points
// the server has located: both only grow.
void WaitUntilStalled(const test::ServerProcess& server,
                      const std::vector<std::unique_ptr<FloodStream>>& floods) {
  auto stub = NewStub(server);
  test::WaitUntilSettled(
      [&] { return TotalWritten(floods) + GetStats(*stub).queries_served(); });
}

// Locate and a stream round trip on a connection of their own.
void ExpectOthersServed(const test::ServerProcess& server) {
  auto stub = NewStub(server);
  v1::LocateResponse response;
  const grpc::Status unary = LocateOne(*stub, {10.25, 20.5}, &response);
  EXPECT_TRUE(unary.ok()) << unary.error_message();
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, std::chrono::seconds(30));
  auto stream = stub->LocateStream(&context);
  EXPECT_TRUE(stream->Write(LocateRequestFor({3.5, 4.25})));
  EXPECT_TRUE(stream->Read(&response));
  stream->WritesDone();
  const grpc::Status streamed = stream->Finish();
  EXPECT_TRUE(streamed.ok()) << streamed.error_message();
}

}  // namespace

grpc::Status FloodWithUnreadStreams(const test::ServerProcess& server) {
  const uint64_t rss_before = ResidentBytes(server.pid());
  auto flooder = NewStub(server);  // one connection for the whole flood
  std::vector<std::unique_ptr<FloodStream>> floods;
  for (int i = 0; i < kFloodStreams; ++i) {
    auto flood = std::make_unique<FloodStream>();
    flood->stream = flooder->LocateStream(&flood->context);
    FloodStream* raw = flood.get();
    flood->writer = std::thread([raw, i] {
      const v1::LocateRequest request = LocateRequestFor({1.0 + i, 2.0});
      while (raw->written.load() < kFloodPoints &&
             raw->stream->Write(request)) {
        ++raw->written;
      }
    });
    floods.push_back(std::move(flood));
  }
  WaitUntilStalled(server, floods);
  const uint64_t written = TotalWritten(floods);
  EXPECT_LT(written, kFloodStreams * kFloodPoints)
      << "the server read every point although no answer was read";
  EXPECT_GT(written, 0u);
  const uint64_t rss_after = ResidentBytes(server.pid());
  if (kRssShowsBuffering) {
    EXPECT_LT(rss_after, rss_before + kFloodRssBound)
        << "resident memory grew from " << rss_before << " to " << rss_after
        << " bytes while " << written << " points were sent unanswered";
  }

  ExpectOthersServed(server);

  grpc::ClientContext extra_context;
  SetDeadlineFromNow(&extra_context, std::chrono::seconds(1));
  auto extra = flooder->LocateStream(&extra_context);
  v1::LocateResponse response;
  EXPECT_FALSE(extra->Write(LocateRequestFor({5, 5})) && extra->Read(&response))
      << "a stream beyond the limit was served";
  const grpc::Status extra_status = extra->Finish();

  for (const auto& flood : floods) flood->context.TryCancel();
  for (const auto& flood : floods) {
    flood->writer.join();
    flood->stream->Finish();
  }
  return extra_status;
}

grpc::Status PingWhileIdle(const test::ServerProcess& server) {
  grpc::ChannelArguments args;
  args.SetInt(GRPC_ARG_KEEPALIVE_TIME_MS, 100);
  args.SetInt(GRPC_ARG_KEEPALIVE_TIMEOUT_MS, 1000);
  args.SetInt(GRPC_ARG_KEEPALIVE_PERMIT_WITHOUT_CALLS, 1);
  // Unlimited and frequent pings without data (a client's own defaults
  // stop at 2, at most one per 5 minutes).
  args.SetInt(GRPC_ARG_HTTP2_MAX_PINGS_WITHOUT_DATA, 0);
  args.SetInt(GRPC_ARG_HTTP2_MIN_SENT_PING_INTERVAL_WITHOUT_DATA_MS, 100);
  args.SetInt(GRPC_ARG_USE_LOCAL_SUBCHANNEL_POOL, 1);
  auto stub = v1::Locator::NewStub(grpc::CreateCustomChannel(
      server.target(), grpc::InsecureChannelCredentials(), args));
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, kPingDuration);
  auto stream = stub->LocateStream(&context);
  v1::LocateResponse response;
  EXPECT_TRUE(stream->Write(LocateRequestFor({1.5, 2.5})) &&
              stream->Read(&response));
  // Idle from here on: no data, only the client's pings.
  EXPECT_FALSE(stream->Read(&response));
  return stream->Finish();
}

}  // namespace locator::test
