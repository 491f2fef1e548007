#include "client/load/run_recorder.h"

#include <algorithm>
#include <utility>

#include "client/locator_client.h"

namespace locator {

RunRecorder::RunRecorder(uint64_t cost_window) : cost_windows_(cost_window) {
  totals_.cost_window = cost_window;
}

void RunRecorder::RecordCall(const Claim& claim, LoadClock::time_point start,
                             LoadClock::time_point end,
                             const grpc::Status& status,
                             std::span<const uint32_t> costs) {
  const auto micros =
      std::chrono::duration_cast<std::chrono::microseconds>(end - start);
  std::lock_guard<std::mutex> lock(mutex_);
  ++interval_.calls;
  for (uint32_t cost : costs) cost_windows_.Add(cost);
  if (!status.ok()) {
    ++interval_.failed_calls;
    ++totals_.errors[std::string(GrpcCodeName(status.error_code()))];
    return;
  }
  if (claim.warmup) {
    ++totals_.warmup_calls;
    return;
  }
  interval_.latency.Record(
      static_cast<uint64_t>(std::max<int64_t>(0, micros.count())));
  ++totals_.calls;
  totals_.points += claim.points;
  totals_.last_end = std::max(totals_.last_end, end);
}

RunInterval RunRecorder::TakeInterval() {
  std::lock_guard<std::mutex> lock(mutex_);
  RunInterval taken = std::exchange(interval_, RunInterval());
  totals_.latency.Merge(taken.latency);
  return taken;
}

RunTotals RunRecorder::Finish() {
  TakeInterval();
  std::lock_guard<std::mutex> lock(mutex_);
  totals_.cost_means = cost_windows_.means();
  return totals_;
}

}  // namespace locator
