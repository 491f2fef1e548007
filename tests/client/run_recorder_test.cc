#include "client/load/run_recorder.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <atomic>
#include <chrono>

#include "client/load/phase_signal.h"

namespace locator {
namespace {

using std::chrono::milliseconds;

const LoadClock::time_point kOrigin = LoadClock::now();

TEST(RunRecorderTest, SplitsCallsIntoPhasesWhenTheCounterMoves) {
  std::atomic<uint32_t> phase{0};
  RecorderOptions options;
  options.origin = kOrigin;
  options.phase_counter = &phase;
  RunRecorder recorder(options);
  const Claim measured{1, false};
  const uint32_t cost = 3;
  const auto call = [&](int end_ms, int latency_ms, const grpc::Status& s) {
    const LoadClock::time_point end = kOrigin + milliseconds(end_ms);
    recorder.RecordCall(measured, end - milliseconds(latency_ms), end, s,
                        s.ok() ? std::span<const uint32_t>(&cost, 1)
                               : std::span<const uint32_t>());
  };
  call(100, 1, grpc::Status::OK);
  call(200, 1, grpc::Status::OK);
  phase = 2;  // two marks before the next call: phase 2 stays empty
  call(3000, 50, grpc::Status(grpc::StatusCode::UNAVAILABLE, "down"));
  call(3500, 20, grpc::Status::OK);

  const RunTotals totals = recorder.Finish();
  ASSERT_EQ(totals.phases.size(), 3u);
  EXPECT_EQ(totals.phases[0].latency.count(), 2u);
  EXPECT_EQ(totals.phases[0].failed_calls, 0u);
  EXPECT_EQ(totals.phases[1].latency.count(), 0u);
  EXPECT_EQ(totals.phases[2].latency.count(), 1u);
  EXPECT_EQ(totals.phases[2].failed_calls, 1u);
  EXPECT_EQ(totals.phases[2].latency.Percentile(99), 20'000u);
  EXPECT_DOUBLE_EQ(totals.phases[2].start_seconds, 3.0);
  // The totals still cover the whole run.
  EXPECT_EQ(totals.calls, 3u);
  EXPECT_EQ(totals.errors.at("UNAVAILABLE"), 1u);
  EXPECT_DOUBLE_EQ(totals.timeline_seconds, 1.0);
  EXPECT_EQ(totals.timeline.size(), 4u);
}

TEST(RunRecorderTest, WithoutACounterTheRunIsOnePhase) {
  RecorderOptions options;
  options.origin = kOrigin;
  RunRecorder recorder(options);
  recorder.RecordCall({1, false}, kOrigin, kOrigin + milliseconds(1),
                      grpc::Status::OK, {});
  const RunTotals totals = recorder.Finish();
  ASSERT_EQ(totals.phases.size(), 1u);
  EXPECT_EQ(totals.phases[0].latency.count(), 1u);
}

TEST(PhaseSignalTest, EachSigusr1MovesTheCounter) {
  const std::atomic<uint32_t>& phase = InstallPhaseSignal();
  const uint32_t before = phase.load();
  // raise() returns after the handler has run in this thread.
  ASSERT_EQ(raise(SIGUSR1), 0);
  ASSERT_EQ(raise(SIGUSR1), 0);
  EXPECT_EQ(phase.load(), before + 2);
}

}  // namespace
}  // namespace locator
