// RunRecorder: what a load run measures. Latencies and throughput counts of
// the measured (non-warm-up) calls, failed calls by status code, the
// server's cost per window of queries in arrival order, the same per phase
// of the run (see phase_signal.h) and a timeline (timeline.h).
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

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "client/load/cost_windows.h"
#include "client/load/latency_histogram.h"
#include "client/load/run_budget.h"
#include "client/load/timeline.h"
#include "common/mutex.h"

namespace locator {

// Calls that ended since the previous TakeInterval().
struct RunInterval {
  LatencyHistogram latency;  // measured successful calls
  uint64_t calls = 0;        // every call that ended, warm-up included
  uint64_t failed_calls = 0;
};

// Calls that ended in one phase of the run.
struct PhaseTotals {
  // When the phase's first call ended, in seconds from the run's start.
  double start_seconds = 0;
  LatencyHistogram latency;   // measured successful calls
  uint64_t failed_calls = 0;  // warm-up included
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
  // At least one; a new one starts whenever the phase counter moves.
  std::vector<PhaseTotals> phases;
  double timeline_seconds = 0;  // the length of a timeline slice
  std::vector<TimelineSlice> timeline;
};

struct RecorderOptions {
  // Average the server's cost over windows of this many queries.
  uint64_t cost_window = 500;
  // The start of the run, and the timeline's slice length (> 0).
  LoadClock::time_point origin;
  LoadClock::duration timeline_slice = std::chrono::seconds(1);
  // A call belongs to the phase this counter shows when the call ends
  // (InstallPhaseSignal()); null: the whole run is one phase.
  const std::atomic<uint32_t>* phase_counter = nullptr;
};

class RunRecorder {
 public:
  explicit RunRecorder(const RecorderOptions& options);

  // Records a call of claim.points points that started at `start` and ended
  // at `end`. `costs` holds the server's cost of each point it answered.
  void RecordCall(const Claim& claim, LoadClock::time_point start,
                  LoadClock::time_point end, const grpc::Status& status,
                  std::span<const uint32_t> costs) EXCLUDES(mutex_);
  // The calls that ended since the previous call (or the start).
  RunInterval TakeInterval() EXCLUDES(mutex_);
  // All that was recorded; call once every call has ended.
  RunTotals Finish() EXCLUDES(mutex_);

 private:
  // The phase a call ending at `end` belongs to, added if new.
  PhaseTotals& PhaseAt(LoadClock::time_point end) REQUIRES(mutex_);

  const RecorderOptions options_;
  Mutex mutex_;
  RunInterval interval_ GUARDED_BY(mutex_);  // not yet merged into totals_
  RunTotals totals_ GUARDED_BY(mutex_);
  CostWindows cost_windows_ GUARDED_BY(mutex_);
  Timeline timeline_ GUARDED_BY(mutex_);
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_RUN_RECORDER_H_
