// WalkCostHistogram: how many faces the walk of each located query visited,
// counted into fixed buckets (the Engine's serving statistics; the metrics
// endpoint exports them as a Prometheus histogram).
//
// Owns one relaxed atomic counter per bucket plus the sum of faces.
// Thread-safety: Add() and AddAll() from any number of threads, concurrently
// with Counts(). A Counts() taken during updates may see a query in its
// bucket but not yet in the sum, or the reverse; fine for a statistic.

#ifndef LOCATOR_CORE_WALK_COST_HISTOGRAM_H_
#define LOCATOR_CORE_WALK_COST_HISTOGRAM_H_

#include <array>
#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

#include "locator/engine_info.h"
#include "locator/locate_result.h"

namespace locator {

class WalkCostHistogram {
 public:
  // Roughly geometric, so both an O(1) jump (a few faces) and a plain walk
  // across a million points (thousands) are resolved.
  static constexpr std::array<uint32_t, 20> kUpperBounds = {
      1,  2,  3,   4,   6,   8,    12,   16,   24,   32,
      48, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384};

  // Counts one walk that visited `faces` faces.
  void Add(uint32_t faces);
  // Counts the walks of `results`, with one update per non-empty bucket.
  void AddAll(std::span<const LocateResult> results);
  WalkCostCounts Counts() const;

 private:
  static size_t BucketOf(uint32_t faces);

  std::array<std::atomic<uint64_t>, kUpperBounds.size() + 1> counts_{};
  std::atomic<uint64_t> faces_sum_{0};
};

}  // namespace locator

#endif  // LOCATOR_CORE_WALK_COST_HISTOGRAM_H_
