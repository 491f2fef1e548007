#include "server/http/status/stats_history.h"

#include <limits>

namespace locator {

void StatsHistory::Record(uint64_t engine_id, uint64_t queries,
                          uint64_t total_cost,
                          std::chrono::system_clock::time_point now) {
  MutexLock lock(&mu_);
  // A new engine's counters start from zero (an address may be reused, so
  // counters that went backwards also mark one).
  if (has_previous_ && (engine_id != engine_id_ || queries < queries_ ||
                        total_cost < total_cost_)) {
    queries_ = 0;
    total_cost_ = 0;
  }
  // The first call only sets the baseline: there is no interval yet.
  if (has_previous_ && now > time_) {
    const double seconds = std::chrono::duration<double>(now - time_).count();
    const uint64_t located = queries - queries_;
    StatsSample sample;
    sample.unix_seconds =
        std::chrono::duration<double>(now.time_since_epoch()).count();
    sample.qps = static_cast<double>(located) / seconds;
    sample.mean_cost =
        located > 0 ? static_cast<double>(total_cost - total_cost_) / located
                    : std::numeric_limits<double>::quiet_NaN();
    samples_.push_back(sample);
    if (samples_.size() > kCapacity) samples_.pop_front();
  }
  has_previous_ = true;
  engine_id_ = engine_id;
  queries_ = queries;
  total_cost_ = total_cost;
  time_ = now;
}

std::vector<StatsSample> StatsHistory::Samples() const {
  MutexLock lock(&mu_);
  return {samples_.begin(), samples_.end()};
}

}  // namespace locator
