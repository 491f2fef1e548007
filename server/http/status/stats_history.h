// StatsHistory: the recent past of an engine's throughput and cost, for the
// status page's charts: one sample per Record() call (locatord records
// about once a second), the last kCapacity kept.
//
// A sample holds the rates over the interval since the previous Record():
// located points per second and their mean cost. When the engine changes
// (a new dataset was published), its counters restart, so the interval is
// measured from zero.
//
// Owns the samples. Thread-safety: all methods may be called concurrently.

#ifndef LOCATOR_SERVER_HTTP_STATS_HISTORY_H_
#define LOCATOR_SERVER_HTTP_STATS_HISTORY_H_

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "common/mutex.h"

namespace locator {

struct StatsSample {
  double unix_seconds = 0;  // when it was taken
  double qps = 0;           // located points per second
  double mean_cost = 0;     // NaN if no point was located in the interval
};

class StatsHistory {
 public:
  static constexpr size_t kCapacity = 300;

  // Records the counters of the engine identified by `engine_id` (any value
  // that differs between engines, e.g. its serving generation), taken at
  // `now`.
  void Record(uint64_t engine_id, uint64_t queries, uint64_t total_cost,
              std::chrono::system_clock::time_point now) EXCLUDES(mu_);

  // The samples, oldest first.
  std::vector<StatsSample> Samples() const EXCLUDES(mu_);

 private:
  mutable Mutex mu_;
  std::deque<StatsSample> samples_ GUARDED_BY(mu_);
  // The previous Record()'s input.
  bool has_previous_ GUARDED_BY(mu_) = false;
  uint64_t engine_id_ GUARDED_BY(mu_) = 0;
  uint64_t queries_ GUARDED_BY(mu_) = 0;
  uint64_t total_cost_ GUARDED_BY(mu_) = 0;
  std::chrono::system_clock::time_point time_ GUARDED_BY(mu_);
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATS_HISTORY_H_
