// ScanLookahead: recognises queries that advance by a constant step, as a
// raster row or a sampled profile does, and predicts the next ones. A
// locator fetches their start faces from memory while the current query
// walks, the way a CPU's stride prefetcher runs ahead of an array scan:
// at a million points each query's start is otherwise a cache miss that
// nothing overlaps.
//
// Only a hint: a wrong prediction costs a few wasted prefetches, never an
// answer.
//
// Thread-safety: Observe() may be called from any thread. The state is
// relaxed atomics; callers that share one instance (threads beyond a
// locator's shards) may spoil each other's predictions, nothing more.
// Invariant: (step_x_, step_y_) is the last difference between observed
// queries, (x_, y_) the last query.

#ifndef LOCATOR_CORE_SCAN_LOOKAHEAD_H_
#define LOCATOR_CORE_SCAN_LOOKAHEAD_H_

#include <atomic>
#include <cmath>

#include "locator/geometry.h"

namespace locator {

class ScanLookahead {
 public:
  // Records q. True when the step from the previous query repeats the one
  // before it (to a relative 1e-6, so that a grid's rounded coordinates
  // qualify) and is finite and not zero; then *step is that step, so that
  // the next queries are predicted at q + k * *step.
  bool Observe(const Point2& q, Point2* step) {
    const double dx = q.x - x_.load(std::memory_order_relaxed);
    const double dy = q.y - y_.load(std::memory_order_relaxed);
    const double last_dx = step_x_.load(std::memory_order_relaxed);
    const double last_dy = step_y_.load(std::memory_order_relaxed);
    x_.store(q.x, std::memory_order_relaxed);
    y_.store(q.y, std::memory_order_relaxed);
    step_x_.store(dx, std::memory_order_relaxed);
    step_y_.store(dy, std::memory_order_relaxed);
    const double size = std::fabs(dx) + std::fabs(dy);
    // Written so that NaN and infinite steps fail.
    if (!(size > 0 && size < kHuge) ||
        !(std::fabs(dx - last_dx) + std::fabs(dy - last_dy) <=
          kTolerance * size)) {
      return false;
    }
    *step = Point2{dx, dy};
    return true;
  }

 private:
  static constexpr double kTolerance = 1e-6;
  static constexpr double kHuge = 1e300;

  std::atomic<double> x_{0};
  std::atomic<double> y_{0};
  std::atomic<double> step_x_{0};
  std::atomic<double> step_y_{0};
};

}  // namespace locator

#endif  // LOCATOR_CORE_SCAN_LOOKAHEAD_H_
