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
#include <mutex>
#include <vector>

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
              std::chrono::system_clock::time_point now);

  // The samples, oldest first.
  std::vector<StatsSample> Samples() const;

 private:
  mutable std::mutex mu_;
  std::deque<StatsSample> samples_;  // guarded by mu_
  // The previous Record()'s input; guarded by mu_.
  bool has_previous_ = false;
  uint64_t engine_id_ = 0;
  uint64_t queries_ = 0;
  uint64_t total_cost_ = 0;
  std::chrono::system_clock::time_point time_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATS_HISTORY_H_
