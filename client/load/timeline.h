// Timeline: what a load run's calls did over time, in slices of equal length
// from the start of the run (warm-up included, as the cost windows do):
// calls, failed calls, latency percentiles and the server's mean cost per
// query in each slice. `locator-load --plot` draws it; the JSON report
// lists it.
//
// A call counts in the slice in which it ended. Owns one LatencyHistogram
// (16 KiB) per slice, added as the run reaches it. Thread-safety: not
// thread-safe; RunRecorder serializes calls.

#ifndef LOCATOR_CLIENT_LOAD_TIMELINE_H_
#define LOCATOR_CLIENT_LOAD_TIMELINE_H_

#include <cstdint>
#include <span>
#include <vector>

#include "client/load/latency_histogram.h"
#include "client/load/run_budget.h"

namespace locator {

// One slice, summarized.
struct TimelineSlice {
  double start_seconds = 0;  // from the start of the run
  uint64_t calls = 0;        // successful calls
  uint64_t failed_calls = 0;
  uint64_t p50_us = 0;  // of the successful calls; 0 when there were none
  uint64_t p99_us = 0;
  uint64_t queries = 0;  // points the server answered, with a cost each
  double mean_cost = 0;  // over those points; 0 when there were none
};

class Timeline {
 public:
  // Slices of `slice` (> 0) each, starting at `origin`.
  Timeline(LoadClock::time_point origin, LoadClock::duration slice);

  double slice_seconds() const;
  // Counts a call that ended at `end` (clamped to the first slice if
  // earlier than `origin`): failed, or successful after `latency_us` with
  // the server's cost of each point in `costs`.
  void Record(LoadClock::time_point end, bool ok, uint64_t latency_us,
              std::span<const uint32_t> costs);
  // Every slice from the first up to the last that a call ended in.
  std::vector<TimelineSlice> Slices() const;

 private:
  struct Slice {
    LatencyHistogram latency;
    uint64_t failed_calls = 0;
    uint64_t queries = 0;
    uint64_t cost_sum = 0;
  };

  const LoadClock::time_point origin_;
  const LoadClock::duration slice_;
  std::vector<Slice> slices_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_TIMELINE_H_
