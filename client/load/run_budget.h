// RunBudget: how long a load run goes on, and which of its calls are
// warm-up.
//
// A run is bounded by time (warm-up seconds, then measured seconds) or by
// count (warm-up queries, then measured queries, within a time limit).
// Runners claim points before every call; once the budget is spent claims
// fail, and the runner only waits for its calls in flight. Counts are of
// points, so a batch run of --queries N locates N points; a batch that
// straddles the end of the warm-up counts as warm-up.
//
// Thread-safety: thread-safe; claims come from any gRPC thread.

#ifndef LOCATOR_CLIENT_LOAD_RUN_BUDGET_H_
#define LOCATOR_CLIENT_LOAD_RUN_BUDGET_H_

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace locator {

using LoadClock = std::chrono::steady_clock;

// How long a run goes on. Exactly one of measured_seconds and
// measured_queries is positive; the warm-up is in the same unit.
struct RunLength {
  double warmup_seconds = 0;
  double measured_seconds = 0;
  uint64_t warmup_queries = 0;
  uint64_t measured_queries = 0;
  // A count-bounded run stops here even if queries are left.
  double time_limit_seconds = 600;

  bool by_count() const { return measured_queries > 0; }
};

// Points granted for one call.
struct Claim {
  size_t points = 0;
  bool warmup = false;
};

class RunBudget {
 public:
  // A budget for `length` starting at `start`.
  RunBudget(const RunLength& length, LoadClock::time_point start);

  // Claims up to `want` points for a call that starts (or, in an open-loop
  // run, was scheduled) at `at`; false once the run is over.
  bool TryClaim(size_t want, LoadClock::time_point at, Claim* claim);
  // When measurement began: the end of a timed warm-up, or when the first
  // measured query of a count-bounded run was claimed (`end()` if none was).
  LoadClock::time_point measure_start() const;
  // No call starts at or after this time.
  LoadClock::time_point end() const { return end_; }

 private:
  const RunLength length_;
  const LoadClock::time_point warmup_end_;  // timed runs only
  const LoadClock::time_point end_;
  std::atomic<uint64_t> claimed_{0};  // points; count-bounded runs only
  // Of the first measured claim, as LoadClock ticks; count-bounded only.
  std::atomic<LoadClock::rep> first_measured_{0};
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_RUN_BUDGET_H_
