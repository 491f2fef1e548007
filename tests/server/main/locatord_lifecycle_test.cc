// locatord's life as a process, end to end: bad flags and exit codes, a
// gRPC address in use, the health transition while loading, re-tunes under
// concurrent load, and the drain on SIGTERM. (Bad datasets and requests: the
// bad-input table.)

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "tests/server/main/e2e_support.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

constexpr auto kExitTimeout = std::chrono::seconds(30);

TEST(LocatordStartupTest, BadFlagExitsTwoWithoutListening) {
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(
      ServerProcess::Spawn(LOCATORD_PATH, {"--threads", "0"}, &server).ok());
  EXPECT_FALSE(server->WaitForListening().ok());
  EXPECT_EQ(server->WaitForExit(kExitTimeout), 2);
  EXPECT_THAT(server->StderrText(), HasSubstr("--threads"));
}

// gRPC would let a second server share the port (SO_REUSEPORT) and take
// some of the first one's connections; locatord refuses to start instead.
TEST(LocatordStartupTest, AGrpcAddressInUseExitsOneAndTheFirstKeepsServing) {
  std::unique_ptr<ServerProcess> first;
  const Status started = StartLocatord("uniform:2000:1", {}, &first);
  ASSERT_TRUE(started.ok()) << started.ToString();
  std::unique_ptr<ServerProcess> second;
  ASSERT_TRUE(ServerProcess::Spawn(
                  LOCATORD_PATH,
                  {"--dataset", "uniform:2000:1", "--listen", first->target()},
                  &second)
                  .ok());
  EXPECT_EQ(second->WaitForExit(kExitTimeout), 1);
  EXPECT_THAT(second->StderrText(),
              HasSubstr("cannot listen on " + first->target()));
  // Every new connection still reaches the first server.
  for (int i = 0; i < 20; ++i) {
    v1::LocateResponse response;
    const grpc::Status status =
        LocateOne(*NewStub(*first), {0.5, 0.5}, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
  }
}

TEST(LocatordStartupTest, HealthGoesFromNotServingToServing) {
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(ServerProcess::Spawn(
                  LOCATORD_PATH,
                  {"--dataset", "uniform:300000:3", "--listen", "127.0.0.1:0"},
                  &server)
                  .ok());
  ASSERT_TRUE(server->WaitForListening().ok());
  // Loading 3 x 10^5 points takes far longer than these two probes, but
  // either one observing the loading state is enough.
  HealthStatus health = HealthStatus::kUnknown;
  const grpc::Status probe = server->CheckHealth(&health);
  auto stub = NewStub(*server);
  v1::LocateResponse response;
  const grpc::Status early = LocateOne(*stub, {0.5, 0.5}, &response);
  const bool saw_not_serving =
      probe.ok() && health == HealthStatus::kNotServing;
  const bool saw_loading =
      early.error_code() == grpc::StatusCode::UNAVAILABLE &&
      early.error_message() == "dataset 'default' is still loading";
  EXPECT_TRUE(saw_not_serving || saw_loading);
  EXPECT_TRUE(early.ok() || saw_loading) << early.error_message();

  const Status serving = server->WaitUntilServing();
  ASSERT_TRUE(serving.ok()) << serving.ToString();
  EXPECT_TRUE(LocateOne(*stub, {0.5, 0.5}, &response).ok());
  EXPECT_THAT(server->StderrText(), HasSubstr("locatord serving "));
}

TEST(LocatordRetuneTest, ConcurrentClientsStayExactThroughRetunes) {
  const TestDatasetFile dataset;
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(dataset.path(), &reference).ok());
  std::unique_ptr<ServerProcess> server;
  const Status started =
      StartLocatord(dataset.path(), {"--retune-every", "500"}, &server);
  ASSERT_TRUE(started.ok()) << started.ToString();
  auto stats_stub = NewStub(*server);
  const uint64_t retunes_before = GetStats(*stats_stub).tuning().retune_count();

  const std::vector<Point2> queries = TestQueries();
  constexpr int kClients = 8;
  constexpr int kRounds = 25;
  constexpr size_t kBatch = 200;
  std::vector<std::string> problems(kClients);
  std::vector<std::thread> clients;
  for (int client = 0; client < kClients; ++client) {
    clients.emplace_back([&, client] {
      auto stub = NewStub(*server);
      std::mt19937_64 rng(client);
      std::uniform_int_distribution<size_t> pick(0, queries.size() - kBatch);
      for (int round = 0; round < kRounds && problems[client].empty();
           ++round) {
        const std::span<const Point2> batch =
            std::span<const Point2>(queries).subspan(pick(rng), kBatch);
        grpc::ClientContext context;
        v1::LocateBatchResponse response;
        const grpc::Status status =
            stub->LocateBatch(&context, BatchRequestFor(batch), &response);
        std::vector<LocateResult> answers;
        for (size_t row = 0; status.ok() && row < kBatch; ++row) {
          answers.push_back(FromBatchRow(response, row));
        }
        // A few unary calls between batches, answered by the same tuning.
        for (size_t k = 0; status.ok() && k < 10; ++k) {
          v1::LocateResponse unary;
          if (!LocateOne(*stub, batch[k], &unary).ok()) break;
          const LocateResult answer = FromLocateResponse(unary);
          problems[client] += reference->Disagreements(
              batch.subspan(k, 1), std::span(&answer, 1), true);
        }
        problems[client] +=
            status.ok() ? reference->Disagreements(batch, answers, false)
                        : status.error_message();
      }
    });
  }
  for (std::thread& client : clients) client.join();
  for (const std::string& problem : problems) EXPECT_EQ(problem, "");

  // Re-tunes run in the background; wait for the last ones to land.
  const uint64_t retunes_after =
      WaitForStats(*stats_stub,
                   [&](const v1::GetStatsResponse& stats) {
                     return stats.tuning().retune_count() >= retunes_before + 2;
                   })
          .tuning()
          .retune_count();
  EXPECT_GE(retunes_after, retunes_before + 2);
}

TEST(LocatordRetuneTest, PeriodicRetunesAndStatsLines) {
  std::unique_ptr<ServerProcess> server;
  const TestDatasetFile dataset;
  const Status started = StartLocatord(
      dataset.path(),
      {"--retune-interval-s", "0.1", "--stats-interval-s", "0.1"}, &server);
  ASSERT_TRUE(started.ok()) << started.ToString();
  auto stub = NewStub(*server);
  const uint64_t retunes =
      WaitForStats(*stub,
                   [](const v1::GetStatsResponse& stats) {
                     return stats.tuning().retune_count() >= 2;
                   })
          .tuning()
          .retune_count();
  EXPECT_GE(retunes, 2u);
  EXPECT_THAT(server->WaitForStderr("stats: queries=", test::kGenerousWait),
              HasSubstr("stats: queries="));
}

// Locate with a deadline, so that a refusal can never hang the test.
grpc::Status LocateWithin(v1::Locator::Stub& stub,
                          std::chrono::seconds deadline) {
  grpc::ClientContext context;
  SetDeadlineFromNow(&context, deadline);
  v1::LocateResponse response;
  return stub.Locate(&context, LocateRequestFor({10.25, 20.5}), &response);
}

TEST(LocatordShutdownTest, SigtermDrainsInFlightCallsAndExitsZero) {
  std::unique_ptr<ServerProcess> server;
  const TestDatasetFile dataset;
  const Status started = StartLocatord(dataset.path(), {}, &server);
  ASSERT_TRUE(started.ok()) << started.ToString();
  const std::vector<Point2> queries = TestQueries();
  auto stub = NewStub(*server);
  // A client that is connected (and idle) when the signal comes.
  auto connected = NewStub(*server);
  ASSERT_TRUE(LocateWithin(*connected, std::chrono::seconds(30)).ok());

  // A stream opened before the signal is in flight by construction: it
  // must keep being answered during the drain and finish OK.
  grpc::ClientContext stream_context;
  auto stream = stub->LocateStream(&stream_context);
  auto round_trip = [&](const Point2& q) {
    v1::LocateResponse response;
    return stream->Write(LocateRequestFor(q)) && stream->Read(&response);
  };
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(round_trip(queries[k]));

  // A batch large enough to take a while; once the server counts queries
  // beyond the stream's, it is being located, so it is in flight too.
  std::vector<Point2> big;
  while (big.size() < 500'000) {
    big.insert(big.end(), queries.begin(), queries.end());
  }
  const uint64_t served_before = GetStats(*stub).queries_served();
  grpc::Status big_status;
  v1::LocateBatchResponse big_response;
  std::thread big_call([&] {
    grpc::ClientContext context;
    big_status =
        stub->LocateBatch(&context, BatchRequestFor(big), &big_response);
  });
  EXPECT_TRUE(test::WaitUntil(
      [&] { return GetStats(*stub).queries_served() > served_before; }));

  // Small batches keep arriving around the signal: those that started
  // before it succeed, the first one after it is refused; none may fail
  // otherwise.
  std::vector<grpc::Status> refusals(4);
  std::vector<std::atomic<int>> small_ok(refusals.size());
  std::vector<std::thread> clients;
  for (size_t client = 0; client < refusals.size(); ++client) {
    clients.emplace_back([&, client] {
      auto client_stub = NewStub(*server);
      const v1::LocateBatchRequest request =
          BatchRequestFor(std::span<const Point2>(queries).subspan(0, 1000));
      for (;;) {
        grpc::ClientContext context;
        v1::LocateBatchResponse response;
        const grpc::Status status =
            client_stub->LocateBatch(&context, request, &response);
        if (!status.ok()) {
          refusals[client] = status;
          return;
        }
        ++small_ok[client];
      }
    });
  }
  // The signal comes once every client has had a batch answered.
  EXPECT_TRUE(test::WaitUntil([&] {
    return std::all_of(small_ok.begin(), small_ok.end(),
                       [](const std::atomic<int>& ok) { return ok > 0; });
  }));
  server->SendSignal(SIGTERM);

  // Once the server has acted on the signal, new calls are refused with
  // UNAVAILABLE (so a client may retry them elsewhere), on the connection
  // it already had and on a new one, while the stream is still open. (Not
  // CANCELLED, as gRPC's own shutdown would answer some: see DrainGate.)
  server->WaitForStderr("draining in-flight calls", kExitTimeout);
  for (const grpc::Status& late :
       {LocateWithin(*connected, std::chrono::seconds(10)),
        LocateWithin(*NewStub(*server), std::chrono::seconds(10))}) {
    EXPECT_EQ(late.error_code(), grpc::StatusCode::UNAVAILABLE)
        << late.error_message();
    EXPECT_EQ(late.error_message(), "server is shutting down");
  }

  for (int k = 10; k < 20; ++k) EXPECT_TRUE(round_trip(queries[k]));
  stream->WritesDone();
  const grpc::Status stream_status = stream->Finish();
  EXPECT_TRUE(stream_status.ok()) << stream_status.error_message();
  big_call.join();
  EXPECT_TRUE(big_status.ok()) << big_status.error_message();
  EXPECT_EQ(big_response.types_size(), static_cast<int>(big.size()));

  for (std::thread& client : clients) client.join();
  for (const grpc::Status& refusal : refusals) {
    EXPECT_EQ(refusal.error_code(), grpc::StatusCode::UNAVAILABLE)
        << refusal.error_message();
    EXPECT_EQ(refusal.error_message(), "server is shutting down");
  }
  // Everything in flight has ended: the process exits 0 well within the
  // drain deadline.
  EXPECT_EQ(server->WaitForExit(kExitTimeout), 0);
}

}  // namespace
}  // namespace locator::test
