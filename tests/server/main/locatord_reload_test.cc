// Reload and SIGHUP end to end: the new dataset is served exactly (CGAL
// agrees), a bad file keeps the old one serving and names file:line (with
// --redact, as the client named it, and no server path), and calls in
// flight during a reload succeed and finish on the old engine.
// (The states during a build, held at a barrier, and the refusal of a second
// reload meanwhile: locator_service_test, in process.)

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

// What the in-flight test reloads.
constexpr char kNextDataset[] = "uniform:20000:5";

TEST(LocatordReloadTest, TheNewDatasetIsServedExactly) {
  const TestDatasetFile first;
  ScratchDir dir;
  const std::string second = dir.path() + "/second.csv";
  WriteUniformCsv(second, 2000, 9);
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(
      StartLocatord(first.path(), {"--reload-dir", dir.path()}, &server).ok());
  auto stub = NewStub(*server);
  EXPECT_EQ(GetStats(*stub).generation(), 1u);

  v1::ReloadResponse response;
  const grpc::Status status = Reload(*stub, second, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.generation(), 2u);
  EXPECT_EQ(response.dataset().source(), second);
  EXPECT_EQ(response.dataset().input_points(), 2000u);
  const v1::GetStatsResponse stats = GetStats(*stub);
  EXPECT_EQ(stats.generation(), 2u);
  EXPECT_FALSE(stats.reload_in_progress());
  EXPECT_EQ(stats.dataset().source(), second);
  EXPECT_EQ(stats.queries_served(), 0u);
  ExpectAnswersAgree(*stub, second);
}

TEST(LocatordReloadTest, AClientOfTheDeprecatedDatasetFieldStillReloads) {
  const TestDatasetFile first;
  ScratchDir dir;
  const std::string second = dir.path() + "/second.csv";
  WriteUniformCsv(second, 2000, 9);
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(
      StartLocatord(first.path(), {"--reload-dir", dir.path()}, &server).ok());
  auto stub = NewStub(*server);

  v1::ReloadRequest request;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  request.set_dataset(second);
#pragma GCC diagnostic pop
  v1::ReloadResponse response;
  grpc::ClientContext context;
  const grpc::Status status = stub->Reload(&context, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.dataset().source(), second);
  EXPECT_EQ(response.dataset().input_points(), 2000u);
}

TEST(LocatordReloadTest, ABadFileKeepsTheOldDatasetServing) {
  const TestDatasetFile first;
  ScratchDir dir;
  const std::string bad = dir.path() + "/bad.csv";
  std::ofstream(bad) << "x,y,z\n0,0,1\n1,oops,2\n";
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(
      StartLocatord(first.path(), {"--reload-dir", dir.path()}, &server).ok());
  auto stub = NewStub(*server);

  v1::ReloadResponse response;
  grpc::Status status = Reload(*stub, bad, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(status.error_message(), HasSubstr(bad + ":3"));
  // A missing file is refused like a file outside the reload dir (see
  // locatord_reload_policy_test.cc).
  status = Reload(*stub, dir.path() + "/missing.csv", &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::PERMISSION_DENIED);

  const v1::GetStatsResponse stats = GetStats(*stub);
  EXPECT_EQ(stats.generation(), 1u);
  EXPECT_EQ(stats.dataset().source(), first.path());
  v1::LocateResponse located;
  EXPECT_TRUE(LocateOne(*stub, {30.5, 20.25}, &located).ok());
  EXPECT_THAT(server->StderrText(),
              HasSubstr("reload failed, still serving the previous dataset"));
}

TEST(LocatordReloadTest, WithRedactAReloadErrorNamesTheFileAsTheClientDid) {
  ScratchDir dir;
  const std::string configured = dir.path() + "/configured.csv";
  WriteUniformCsv(configured, 500, 1);
  std::ofstream(dir.path() + "/bad.csv") << "x,y,z\n0,0,1\n1,oops,2\n";
  WriteUniformCsv(dir.path() + "/points.csv", 500, 2);
  std::ofstream(dir.path() + "/lines.wkt") << "LINESTRING (0.1 0.1, oops)\n";
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(StartLocatord(configured,
                            {"--redact", "--reload-dir", dir.path()}, &server)
                  .ok());
  auto stub = NewStub(*server);
  const auto reload_error = [&](const std::string& spec) {
    v1::ReloadResponse response;
    const grpc::Status status = Reload(*stub, spec, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT)
        << spec << ": " << status.error_message();
    return status.error_message();
  };

  // Named relative to the reload dir.
  const std::string relative = reload_error("bad.csv");
  EXPECT_THAT(relative, StartsWith("bad.csv:3: 'oops' is not a number"));
  EXPECT_THAT(relative, Not(HasSubstr(dir.path())));
  // A file the loader reaches through the spec: by its file name.
  const std::string reached = reload_error("points.csv+lines.wkt");
  EXPECT_THAT(reached, StartsWith("lines.wkt:1:"));
  EXPECT_THAT(reached, Not(HasSubstr(dir.path())));
  // The configured dataset, broken after the start: by the dataset's name.
  std::ofstream(configured) << "x,y,z\n0,0,1\n1,2,oops\n";
  const std::string configured_error = reload_error("");
  EXPECT_THAT(configured_error,
              StartsWith("dataset 'default':3: 'oops' is not a number"));
  EXPECT_THAT(configured_error, Not(HasSubstr(dir.path())));
  // Named absolutely: the path the client gave, which it knows already.
  EXPECT_THAT(reload_error(dir.path() + "/bad.csv"),
              StartsWith(dir.path() + "/bad.csv:3: 'oops' is not a number"));
  EXPECT_EQ(GetStats(*stub).generation(), 1u);
}

TEST(LocatordReloadTest, SighupReloadsTheConfiguredDataset) {
  ScratchDir dir;
  const std::string path = dir.path() + "/points.csv";
  WriteUniformCsv(path, 1500, 3);
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(StartLocatord(path, {}, &server).ok());
  auto stub = NewStub(*server);
  EXPECT_EQ(GetStats(*stub).dataset().input_points(), 1500u);

  WriteUniformCsv(path, 2500, 4);
  server->SendSignal(SIGHUP);
  const v1::GetStatsResponse stats = WaitForStats(
      *stub, [](const v1::GetStatsResponse& s) { return s.generation() == 2; });
  ASSERT_EQ(stats.generation(), 2u) << server->StderrText();
  EXPECT_EQ(stats.dataset().input_points(), 2500u);
  EXPECT_THAT(server->StderrText(), HasSubstr("SIGHUP: reloading " + path));
  // The outcome is logged just after the new engine is published.
  const std::string logged = "reloaded: serving " +
                             std::to_string(stats.dataset().triangles()) +
                             " triangles as generation 2";
  EXPECT_THAT(server->WaitForStderr(logged, std::chrono::seconds(30)),
              HasSubstr(logged));
  ExpectAnswersAgree(*stub, path);
}

TEST(LocatordReloadTest, CallsInFlightFinishOnTheOldEngine) {
  const TestDatasetFile first;
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(first.path(), &reference).ok());
  // A reload dir lets Reload load kBigDataset, a generator spec.
  ScratchDir reload_dir;
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(
      StartLocatord(first.path(), {"--reload-dir", reload_dir.path()}, &server)
          .ok());
  auto stub = NewStub(*server);
  const std::vector<Point2> queries = TestQueries();

  // A stream opened before the reload keeps the engine it started with.
  grpc::ClientContext stream_context;
  auto stream = stub->LocateStream(&stream_context);
  size_t next = 0;
  std::string stream_problems;
  auto round_trips = [&](size_t count) {
    for (size_t k = 0; k < count; ++k, ++next) {
      const Point2& q = queries[next % queries.size()];
      v1::LocateResponse response;
      if (!stream->Write(LocateRequestFor(q)) || !stream->Read(&response)) {
        stream_problems += "stream broke\n";
        return;
      }
      const LocateResult answer = FromLocateResponse(response);
      stream_problems += reference->Disagreements(std::span(&q, 1),
                                                  std::span(&answer, 1), true);
    }
  };
  round_trips(20);

  grpc::Status reload_status;
  v1::ReloadResponse reload_response;
  std::thread reload([&] {
    auto reload_stub = NewStub(*server);
    reload_status = Reload(*reload_stub, kNextDataset, &reload_response);
  });
  // Batches from other clients keep running until the swap (each client's
  // first batch at least, whenever the swap comes).
  std::atomic<bool> swapped{false};
  std::atomic<int> batches_ok{0};
  std::vector<grpc::Status> batch_failures(2);
  std::vector<std::thread> clients;
  for (grpc::Status& failure : batch_failures) {
    clients.emplace_back([&] {
      auto client_stub = NewStub(*server);
      const v1::LocateBatchRequest request =
          BatchRequestFor(std::span(queries).subspan(0, 500));
      do {
        grpc::ClientContext context;
        v1::LocateBatchResponse response;
        failure = client_stub->LocateBatch(&context, request, &response);
        if (!failure.ok()) return;
        ++batches_ok;
      } while (!swapped.load());
    });
  }

  round_trips(20);

  reload.join();
  swapped.store(true);
  for (std::thread& client : clients) client.join();
  ASSERT_TRUE(reload_status.ok()) << reload_status.error_message();
  EXPECT_EQ(reload_response.generation(), 2u);
  EXPECT_EQ(GetStats(*stub).dataset().source(), kNextDataset);
  for (const grpc::Status& failure : batch_failures) {
    EXPECT_TRUE(failure.ok()) << failure.error_message();
  }
  EXPECT_GE(batches_ok.load(), static_cast<int>(batch_failures.size()));

  // After the swap the old stream still answers from the old dataset.
  round_trips(20);
  stream->WritesDone();
  const grpc::Status stream_status = stream->Finish();
  EXPECT_TRUE(stream_status.ok()) << stream_status.error_message();
  EXPECT_EQ(stream_problems, "");
}

}  // namespace
}  // namespace locator::test
