// The summary `locator-load` prints at the end of a run: as text for people
// or as one JSON object for scripts (--format json).
//
// JSON fields: mode, workload, target, channels, concurrency, rate,
// batch_size, window, measured_seconds, calls, points, warmup_calls,
// failed_calls, calls_per_second, points_per_second, latency_us {count,
// mean, p50, p90, p99, p99_9, max}, errors {CODE: count}, cost_window,
// cost_window_means [...], phases [{start_seconds, calls, failed_calls,
// latency_us {...}}] (one unless --phase-signal split the run),
// timeline_seconds, timeline [{start_seconds, calls, failed_calls, p50_us,
// p99_us, queries, mean_cost}]. Counts are of measured successful calls,
// except failed_calls and errors, which include the warm-up, and the
// timeline, which covers the warm-up too. Text shows the phases when there
// are several.
//
// Thread-safety: stateless functions.

#ifndef LOCATOR_CLIENT_LOAD_LOAD_REPORT_H_
#define LOCATOR_CLIENT_LOAD_LOAD_REPORT_H_

#include <cstdint>
#include <string>

#include "client/load/load_options.h"
#include "client/load/run_recorder.h"

namespace locator {

// The measured part of a run, ready to print.
struct LoadReport {
  RunTotals totals;
  // From the end of the warm-up to the end of the last measured call.
  double measured_seconds = 0;

  uint64_t failed_calls() const;
  double calls_per_second() const;
  double points_per_second() const;
};

// "unary, closed loop, 64 in flight; workload uniform; 2 channels to T".
std::string DescribeRun(const LoadOptions& options);

std::string FormatReportText(const LoadOptions& options,
                             const LoadReport& report);
std::string FormatReportJson(const LoadOptions& options,
                             const LoadReport& report);

// "850 us", "12.3 ms", "1.20 s": short and readable.
std::string FormatMicros(uint64_t micros);

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_LOAD_REPORT_H_
