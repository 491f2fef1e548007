#include "client/load/run_recorder.h"

#include <algorithm>
#include <utility>

#include "client/locator_client.h"
#include "common/grpc_code_name.h"

namespace locator {

RunRecorder::RunRecorder(const RecorderOptions& options)
    : options_(options),
      cost_windows_(options.cost_window),
      timeline_(options.origin, options.timeline_slice) {
  totals_.cost_window = options.cost_window;
  totals_.phases.emplace_back();
}

PhaseTotals& RunRecorder::PhaseAt(LoadClock::time_point end) {
  const size_t phase =
      options_.phase_counter == nullptr
          ? 0
          : options_.phase_counter->load(std::memory_order_relaxed);
  // Phases marked while no call ended stay in the list, empty, so that
  // phase i is always the one after the i-th mark.
  while (totals_.phases.size() <= phase) {
    totals_.phases.emplace_back().start_seconds =
        std::chrono::duration<double>(end - options_.origin).count();
  }
  return totals_.phases[phase];
}

void RunRecorder::RecordCall(const Claim& claim, LoadClock::time_point start,
                             LoadClock::time_point end,
                             const grpc::Status& status,
                             std::span<const uint32_t> costs) {
  const auto micros = static_cast<uint64_t>(std::max<int64_t>(
      0, std::chrono::duration_cast<std::chrono::microseconds>(end - start)
             .count()));
  MutexLock lock(&mutex_);
  ++interval_.calls;
  for (uint32_t cost : costs) cost_windows_.Add(cost);
  timeline_.Record(end, status.ok(), micros, costs);
  PhaseTotals& phase = PhaseAt(end);
  if (!status.ok()) {
    ++interval_.failed_calls;
    ++phase.failed_calls;
    ++totals_.errors[std::string(GrpcCodeName(status.error_code()))];
    return;
  }
  if (claim.warmup) {
    ++totals_.warmup_calls;
    return;
  }
  interval_.latency.Record(micros);
  phase.latency.Record(micros);
  ++totals_.calls;
  totals_.points += claim.points;
  totals_.last_end = std::max(totals_.last_end, end);
}

RunInterval RunRecorder::TakeInterval() {
  MutexLock lock(&mutex_);
  RunInterval taken = std::exchange(interval_, RunInterval());
  totals_.latency.Merge(taken.latency);
  return taken;
}

RunTotals RunRecorder::Finish() {
  TakeInterval();
  MutexLock lock(&mutex_);
  totals_.cost_means = cost_windows_.means();
  totals_.timeline_seconds = timeline_.slice_seconds();
  totals_.timeline = timeline_.Slices();
  return totals_;
}

}  // namespace locator
