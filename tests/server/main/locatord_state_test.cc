// locatord --state-dir end to end: a server stopped with SIGTERM after
// learning a hot spot answers the first queries of its next life at tuned
// cost (compared, as a ratio, with a server started without state); an
// unusable state file is ignored with a warning naming the reason.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "common/workload.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;

constexpr char kDataset[] = "uniform:50000:42";
constexpr uint64_t kTrainingRounds = 3;
constexpr size_t kQueriesPerRound = 1200;
// Fewer than --retune-every: these are all answered by the start table the
// server started with.
constexpr size_t kFirstQueries = 200;
constexpr auto kExitTimeout = std::chrono::seconds(30);

// A small budget, so that the table tuned for the hot spot serves it
// clearly better than an untuned one. (A reload dir lets Reload load
// generator specs.)
std::vector<std::string> Flags(const std::string& state_dir) {
  return {"--budget",    "32KiB",   "--retune-every", "1000",
          "--state-dir", state_dir, "--reload-dir",   state_dir};
}

std::unique_ptr<ServerProcess> Start(const std::string& state_dir) {
  std::unique_ptr<ServerProcess> server;
  const Status started = StartLocatord(kDataset, Flags(state_dir), &server);
  EXPECT_TRUE(started.ok()) << started.ToString();
  return server;
}

std::vector<Point2> Clustered(v1::Locator::Stub& stub, size_t n,
                              uint64_t seed) {
  const v1::BoundingBox box = GetStats(stub).dataset().bounding_box();
  return WorkloadQueries(
      WorkloadKind::kOneCluster,
      BoundingBox{box.min_x(), box.min_y(), box.max_x(), box.max_y()}, n, seed);
}

// Mean Cost.total of unary Locate calls for `queries`, in order.
double MeanCost(const ServerProcess& server,
                const std::vector<Point2>& queries) {
  auto stub = NewStub(server);
  double sum = 0;
  for (const Point2& q : queries) {
    v1::LocateResponse response;
    const grpc::Status status = LocateOne(*stub, q, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
    sum += response.cost().total();
  }
  return sum / static_cast<double>(queries.size());
}

// Sends rounds of more than --retune-every clustered queries, each waiting
// for its re-tune (the tuner thread folds requests that arrive while it
// works), until the tuning has been saved. Returns the stats then.
v1::GetStatsResponse TrainOnTheHotSpot(v1::Locator::Stub& stub) {
  v1::GetStatsResponse stats = GetStats(stub);
  const uint64_t retunes_before = stats.tuning().retune_count();
  for (uint64_t round = 1; round <= kTrainingRounds; ++round) {
    grpc::ClientContext context;
    v1::LocateBatchResponse response;
    EXPECT_TRUE(stub.LocateBatch(&context,
                                 BatchRequestFor(
                                     Clustered(stub, kQueriesPerRound, round)),
                                 &response)
                    .ok());
    stats = WaitForStats(stub, [&](const v1::GetStatsResponse& s) {
      return s.tuning().retune_count() >= retunes_before + round &&
             s.tuning().persistence().saves() >= 1;
    });
    EXPECT_GE(stats.tuning().retune_count(), retunes_before + round);
  }
  return stats;
}

void StopWithSigterm(ServerProcess* server) {
  server->SendSignal(SIGTERM);
  EXPECT_EQ(server->WaitForExit(kExitTimeout), 0) << server->StderrText();
}

TEST(LocatordStateTest, ARestartedServerAnswersItsFirstQueriesTuned) {
  ScratchDir state_dir;
  uint64_t retunes_before_stop = 0;
  {
    const std::unique_ptr<ServerProcess> trained = Start(state_dir.path());
    ASSERT_NE(trained, nullptr);
    auto stub = NewStub(*trained);
    const v1::GetStatsResponse stats = TrainOnTheHotSpot(*stub);
    retunes_before_stop = stats.tuning().retune_count();
    ASSERT_GE(stats.tuning().persistence().saves(), 1u);
    StopWithSigterm(trained.get());
  }
  ASSERT_EQ(state_dir.Entries().size(), 1u);

  ScratchDir empty_dir;
  const std::unique_ptr<ServerProcess> restored = Start(state_dir.path());
  const std::unique_ptr<ServerProcess> fresh = Start(empty_dir.path());
  ASSERT_NE(restored, nullptr);
  ASSERT_NE(fresh, nullptr);
  auto stub = NewStub(*restored);
  const v1::GetStatsResponse stats = GetStats(*stub);
  const v1::TuningPersistence& persistence = stats.tuning().persistence();
  EXPECT_TRUE(persistence.restored_from_state());
  EXPECT_EQ(persistence.load_error(), "");
  EXPECT_EQ(persistence.state_path(),
            state_dir.path() + "/" + state_dir.Entries()[0]);
  EXPECT_GE(stats.tuning().retune_count(), retunes_before_stop);
  EXPECT_FALSE(
      GetStats(*NewStub(*fresh)).tuning().persistence().restored_from_state());
  EXPECT_THAT(
      restored->StderrText(),
      HasSubstr("restored the tuning state from " + persistence.state_path()));

  const std::vector<Point2> first =
      Clustered(*stub, kFirstQueries, kTrainingRounds + 1);
  const double restored_cost = MeanCost(*restored, first);
  const double fresh_cost = MeanCost(*fresh, first);
  std::cout << "mean cost of the first " << kFirstQueries
            << " clustered queries: restored " << restored_cost << ", fresh "
            << fresh_cost << ", ratio " << restored_cost / fresh_cost
            << std::endl;
  EXPECT_LT(restored_cost, 0.75 * fresh_cost);
}

TEST(LocatordStateTest, AnUnusableStateFileIsIgnoredWithAWarning) {
  ScratchDir state_dir;
  std::string path;
  {
    const std::unique_ptr<ServerProcess> first = Start(state_dir.path());
    ASSERT_NE(first, nullptr);
    path = GetStats(*NewStub(*first)).tuning().persistence().state_path();
    StopWithSigterm(first.get());
  }
  // Nothing was learned, so nothing was written.
  EXPECT_TRUE(state_dir.Entries().empty());
  std::ofstream(path) << "this is not a tuning state, only some text\n";

  const std::unique_ptr<ServerProcess> server = Start(state_dir.path());
  ASSERT_NE(server, nullptr);
  auto stub = NewStub(*server);
  const v1::TuningPersistence persistence =
      GetStats(*stub).tuning().persistence();
  EXPECT_FALSE(persistence.restored_from_state());
  EXPECT_THAT(persistence.load_error(), HasSubstr("bad magic"));
  EXPECT_THAT(server->StderrText(),
              HasSubstr("warning: ignoring the tuning state " + path +
                        ": not a tuning state file (bad magic)"));
  v1::LocateResponse response;
  EXPECT_TRUE(LocateOne(*stub, {0.5, 0.5}, &response).ok());
}

TEST(LocatordStateTest, AReloadStartsFromTheStateOfItsDataset) {
  ScratchDir state_dir;
  const std::unique_ptr<ServerProcess> server = Start(state_dir.path());
  ASSERT_NE(server, nullptr);
  auto stub = NewStub(*server);
  TrainOnTheHotSpot(*stub);
  const uint64_t retunes = GetStats(*stub).tuning().retune_count();

  // The same points again: the outgoing engine saved first, the new one
  // continues from it.
  grpc::ClientContext same_context;
  v1::ReloadRequest same;
  v1::ReloadResponse reloaded;
  ASSERT_TRUE(stub->Reload(&same_context, same, &reloaded).ok());
  EXPECT_TRUE(reloaded.tuning().persistence().restored_from_state());
  EXPECT_GE(reloaded.tuning().retune_count(), retunes);

  // Other points: another fingerprint, no state yet.
  grpc::ClientContext other_context;
  v1::ReloadRequest other;
  other.set_dataset("uniform:20000:7");
  ASSERT_TRUE(stub->Reload(&other_context, other, &reloaded).ok());
  EXPECT_FALSE(reloaded.tuning().persistence().restored_from_state());
  EXPECT_EQ(reloaded.tuning().persistence().load_error(), "");
  EXPECT_EQ(reloaded.tuning().retune_count(), 0u);
  EXPECT_EQ(state_dir.Entries().size(), 1u);
}

}  // namespace
}  // namespace locator::test
