// RunRecorder: what a load run measures. Latencies and throughput counts of
// the measured (non-warm-up) calls, failed calls by status code, and the
// server's cost per window of queries in arrival order.
//
// Latency is recorded for successful calls only, from the call's start (its
// scheduled start in an open-loop run) to its completion. Failed calls,
// warm-up included, are counted by code and never timed.
//
// Owns the histograms and counters. Thread-safety: thread-safe; calls end on
// gRPC threads while the progress line reads intervals from another.

#ifndef LOCATOR_CLIENT_LOAD_RUN_RECORDER_H_
#define LOCATOR_CLIENT_LOAD_RUN_RECORDER_H_

#include <grpcpp/grpcpp.h>

#include <cstdint>
#include <map>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "client/load/cost_windows.h"
#include "client/load/latency_histogram.h"
#include "client/load/run_budget.h"

namespace locator {

// Calls that ended since the previous TakeInterval().
struct RunInterval {
  LatencyHistogram latency;  // measured successful calls
  uint64_t calls = 0;        // every call that ended, warm-up included
  uint64_t failed_calls = 0;
};

// Everything a run recorded.
struct RunTotals {
  LatencyHistogram latency;
  uint64_t calls = 0;   // measured successful calls
  uint64_t points = 0;  // points they located
  uint64_t warmup_calls = 0;
  // Failed calls (warm-up included) by status code name.
  std::map<std::string, uint64_t> errors;
  uint64_t cost_window = 0;
  std::vector<double> cost_means;
  // When the last measured successful call ended.
  LoadClock::time_point last_end;
};

class RunRecorder {
 public:
  // Averages the server's cost over windows of `cost_window` queries.
  explicit RunRecorder(uint64_t cost_window);

  // Records a call of claim.points points that started at `start` and ended
  // at `end`. `costs` holds the server's cost of each point it answered.
  void RecordCall(const Claim& claim, LoadClock::time_point start,
                  LoadClock::time_point end, const grpc::Status& status,
                  std::span<const uint32_t> costs);
  // The calls that ended since the previous call (or the start).
  RunInterval TakeInterval();
  // All that was recorded; call once every call has ended.
  RunTotals Finish();

 private:
  std::mutex mutex_;
  RunInterval interval_;  // not yet merged into totals_
  RunTotals totals_;
  CostWindows cost_windows_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_RUN_RECORDER_H_
