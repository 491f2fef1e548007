#include "client/load/run_budget.h"

#include <algorithm>

namespace locator {
namespace {

LoadClock::duration Seconds(double seconds) {
  return std::chrono::duration_cast<LoadClock::duration>(
      std::chrono::duration<double>(seconds));
}

}  // namespace

RunBudget::RunBudget(const RunLength& length, LoadClock::time_point start)
    : length_(length),
      warmup_end_(start + Seconds(length.warmup_seconds)),
      end_(length.by_count() ? start + Seconds(length.time_limit_seconds)
                             : warmup_end_ + Seconds(length.measured_seconds)) {
}

bool RunBudget::TryClaim(size_t want, LoadClock::time_point at, Claim* claim) {
  if (at >= end_) return false;
  if (!length_.by_count()) {
    *claim = Claim{want, at < warmup_end_};
    return true;
  }
  const uint64_t total = length_.warmup_queries + length_.measured_queries;
  const uint64_t before = claimed_.fetch_add(want);
  if (before >= total) return false;
  *claim = Claim{static_cast<size_t>(std::min<uint64_t>(want, total - before)),
                 before < length_.warmup_queries};
  if (!claim->warmup) {
    LoadClock::rep unset = 0;
    first_measured_.compare_exchange_strong(unset,
                                            at.time_since_epoch().count());
  }
  return true;
}

LoadClock::time_point RunBudget::measure_start() const {
  if (!length_.by_count()) return warmup_end_;
  const LoadClock::rep first = first_measured_.load();
  return first == 0 ? end_ : LoadClock::time_point(LoadClock::duration(first));
}

}  // namespace locator
