// TinProgressReporter: the progress of one TIN build, gathered from its
// builders (one slot each: a tile, or the whole grid) and passed to
// TinOptions::progress at least every progress_interval_s seconds, as long
// as the builders call Update() often (greedy insertion does every few
// hundred points).
//
// Thread-safety: Update() and Report() from any thread; the callback is
// called under a mutex, never two calls at once.

#ifndef LOCATOR_CORE_TERRAIN_TIN_PROGRESS_H_
#define LOCATOR_CORE_TERRAIN_TIN_PROGRESS_H_

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "common/mutex.h"
#include "common/thread_annotations.h"
#include "server/core/terrain/tin_options.h"

namespace locator {

class TinProgressReporter {
 public:
  // `slots` builders; the clock starts now.
  TinProgressReporter(const TinOptions& options, size_t slots);

  // Builder `slot` now keeps `vertices` vertices and its largest error is
  // `error`; reports if the interval has passed since the last report.
  void Update(size_t slot, uint64_t vertices, double error) EXCLUDES(mu_);
  // All builders are now one (slot 0): the tiles were merged.
  void Merged(uint64_t vertices, double error) EXCLUDES(mu_);
  // Reports if the interval has passed (for phases without vertices).
  void Poll() EXCLUDES(mu_);
  // Seconds since construction.
  double seconds() const;

 private:
  const TinOptions& options_;
  const std::chrono::steady_clock::time_point start_;
  const size_t slots_;
  std::unique_ptr<std::atomic<uint64_t>[]> vertices_;
  std::unique_ptr<std::atomic<double>[]> errors_;
  // Nanoseconds since start_ when the next report is due.
  std::atomic<int64_t> next_due_ns_;
  Mutex mu_;  // serialises the callback
};

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_TIN_PROGRESS_H_
