#include "server/core/walk_cost_histogram.h"

#include <algorithm>

namespace locator {

size_t WalkCostHistogram::BucketOf(uint32_t faces) {
  return static_cast<size_t>(
      std::lower_bound(kUpperBounds.begin(), kUpperBounds.end(), faces) -
      kUpperBounds.begin());
}

void WalkCostHistogram::Add(uint32_t faces) {
  counts_[BucketOf(faces)].fetch_add(1, std::memory_order_relaxed);
  faces_sum_.fetch_add(faces, std::memory_order_relaxed);
}

void WalkCostHistogram::AddAll(std::span<const LocateResult> results) {
  // Tallied locally first: a batch chunk then costs a handful of shared
  // atomic updates instead of two per point.
  std::array<uint64_t, kUpperBounds.size() + 1> tally{};
  uint64_t faces_sum = 0;
  for (const LocateResult& r : results) {
    ++tally[BucketOf(r.cost.faces_visited)];
    faces_sum += r.cost.faces_visited;
  }
  for (size_t i = 0; i < tally.size(); ++i) {
    if (tally[i] > 0) counts_[i].fetch_add(tally[i], std::memory_order_relaxed);
  }
  faces_sum_.fetch_add(faces_sum, std::memory_order_relaxed);
}

WalkCostCounts WalkCostHistogram::Counts() const {
  WalkCostCounts out;
  out.upper_bounds.assign(kUpperBounds.begin(), kUpperBounds.end());
  for (const std::atomic<uint64_t>& count : counts_) {
    out.counts.push_back(count.load(std::memory_order_relaxed));
  }
  out.faces_sum = faces_sum_.load(std::memory_order_relaxed);
  return out;
}

}  // namespace locator
