#include "client/load/timeline.h"

#include <algorithm>
#include <chrono>

namespace locator {

Timeline::Timeline(LoadClock::time_point origin, LoadClock::duration slice)
    : origin_(origin), slice_(slice) {}

double Timeline::slice_seconds() const {
  return std::chrono::duration<double>(slice_).count();
}

void Timeline::Record(LoadClock::time_point end, bool ok, uint64_t latency_us,
                      std::span<const uint32_t> costs) {
  // A call may be stamped before `origin` when the recorder was created
  // after the run's clock started; it belongs to the first slice.
  const auto since = std::max(end - origin_, LoadClock::duration::zero());
  const auto index = static_cast<size_t>(since / slice_);
  if (index >= slices_.size()) slices_.resize(index + 1);
  Slice& slice = slices_[index];
  if (ok) {
    slice.latency.Record(latency_us);
  } else {
    ++slice.failed_calls;
  }
  slice.queries += costs.size();
  for (uint32_t cost : costs) slice.cost_sum += cost;
}

std::vector<TimelineSlice> Timeline::Slices() const {
  std::vector<TimelineSlice> summaries;
  summaries.reserve(slices_.size());
  for (size_t i = 0; i < slices_.size(); ++i) {
    const Slice& slice = slices_[i];
    TimelineSlice summary;
    summary.start_seconds = static_cast<double>(i) * slice_seconds();
    summary.calls = slice.latency.count();
    summary.failed_calls = slice.failed_calls;
    summary.p50_us = slice.latency.Percentile(50);
    summary.p99_us = slice.latency.Percentile(99);
    summary.queries = slice.queries;
    summary.mean_cost = slice.queries == 0
                            ? 0.0
                            : static_cast<double>(slice.cost_sum) /
                                  static_cast<double>(slice.queries);
    summaries.push_back(summary);
  }
  return summaries;
}

}  // namespace locator
