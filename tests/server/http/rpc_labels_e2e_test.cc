// /metrics labels only the gRPC methods locatord serves: calls of methods a
// client makes up (10,000 distinct names, over one channel, as a scan
// would) are counted under one "unknown" label, so that /metrics stays
// small and names none of them.

#include <gmock/gmock.h>
#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "tests/server/http/http_test_client.h"
#include "tests/server/http/prometheus_text.h"
#include "tests/server/http/status_e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Calls each of `methods` once with an empty request over `channel`, at
// most kInFlight at a time; returns how many calls ended with each code.
std::map<grpc::StatusCode, int> CallEach(
    const std::shared_ptr<grpc::Channel>& channel,
    const std::vector<std::string>& methods) {
  constexpr int kInFlight = 64;
  struct Call {
    grpc::ClientContext context;
    // A ByteBuffer without a slice is no message at all to gRPC.
    grpc::Slice empty;
    grpc::ByteBuffer request{&empty, 1};
    grpc::ByteBuffer response;
  };
  grpc::GenericStub stub(channel);
  std::mutex mu;
  std::condition_variable ended;
  int in_flight = 0;
  std::map<grpc::StatusCode, int> codes;
  // Every call's context lives until all calls have ended: gRPC may still
  // use one after its callback has run, so none is destroyed from there.
  std::vector<std::unique_ptr<Call>> calls;
  calls.reserve(methods.size());
  for (const std::string& method : methods) {
    {
      std::unique_lock lock(mu);
      ended.wait(lock, [&] { return in_flight < kInFlight; });
      ++in_flight;
    }
    Call* call = calls.emplace_back(std::make_unique<Call>()).get();
    call->context.set_deadline(std::chrono::system_clock::now() +
                               std::chrono::seconds(60));
    stub.UnaryCall(&call->context, method, grpc::StubOptions(), &call->request,
                   &call->response, [&](const grpc::Status& status) {
                     std::lock_guard lock(mu);
                     ++codes[status.error_code()];
                     --in_flight;
                     ended.notify_one();
                   });
  }
  std::unique_lock lock(mu);
  ended.wait(lock, [&] { return in_flight == 0; });
  return codes;
}

TEST(RpcLabelsTest, UnknownMethodsAreCountedUnderOneLabel) {
  std::unique_ptr<LocatordWithHttp> server;
  const Status started = LocatordWithHttp::Start("uniform:2000:1", {}, &server);
  ASSERT_TRUE(started.ok()) << started.ToString();
  // Made-up methods of made-up services and of locator.v1.Locator itself.
  constexpr int kCalls = 10'000;
  std::vector<std::string> methods;
  for (int i = 0; i < kCalls; ++i) {
    methods.push_back(i % 2 == 0
                          ? "/probe.Bogus" + std::to_string(i) + "/Bogus" +
                                std::to_string(i)
                          : "/locator.v1.Locator/Bogus" + std::to_string(i));
  }
  const std::map<grpc::StatusCode, int> codes =
      CallEach(grpc::CreateChannel(server->grpc_target(),
                                   grpc::InsecureChannelCredentials()),
               methods);
  EXPECT_EQ(codes, (std::map<grpc::StatusCode, int>{
                       {grpc::StatusCode::UNIMPLEMENTED, kCalls}}));
  // The server's own methods keep their labels.
  v1::LocateResponse located;
  ASSERT_TRUE(LocateOne(*server->NewStub(), {0.5, 0.5}, &located).ok());

  HttpReply reply;
  ASSERT_TRUE(HttpGet(server->http_port(), "/metrics", &reply).ok());
  ASSERT_EQ(reply.status, 200u);
  EXPECT_LT(reply.body.size(), size_t{1} << 20);
  EXPECT_THAT(reply.body, Not(HasSubstr("Bogus")));
  PrometheusText metrics;
  const Status parsed = ParsePrometheusText(reply.body, &metrics);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(
      metrics.Value("locator_rpc_requests_total", {{"service", "unknown"},
                                                   {"method", "unknown"},
                                                   {"code", "UNIMPLEMENTED"}}),
      kCalls);
  EXPECT_EQ(metrics.Value("locator_rpc_requests_total",
                          {{"service", "locator.v1.Locator"},
                           {"method", "Locate"},
                           {"code", "OK"}}),
            1);
}

}  // namespace
}  // namespace locator::test
