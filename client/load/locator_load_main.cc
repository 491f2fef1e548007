// locator-load: drives a locator server with a bounded load and reports what
// it measured (see LoadUsage() in client/load/load_options.cc).
//
// It only talks to --target, and every loop stops by itself: at the end of
// --duration, or after --queries queries (or --time-limit).

#include <atomic>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "client/load/call_loops.h"
#include "client/load/client_pool.h"
#include "client/load/load_options.h"
#include "client/load/load_plot.h"
#include "client/load/load_report.h"
#include "client/load/locator_calls.h"
#include "client/load/nested_batch_calls.h"
#include "client/load/phase_signal.h"
#include "client/load/progress_line.h"
#include "client/load/query_source.h"
#include "client/load/run_budget.h"
#include "client/load/run_recorder.h"
#include "client/load/stream_runner.h"
#include "common/grpc_lifetime.h"

namespace locator {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitCallsFailed = 1;
constexpr int kExitUsage = 2;

std::unique_ptr<CallStarter> MakeCallStarter(const LoadOptions& options,
                                             ClientPool& pool,
                                             QuerySource& source) {
  switch (options.mode) {
    case LoadMode::kBatch: {
      BatchColumns columns;
      if (options.all_columns) columns = {true, true, true};
      return std::make_unique<BatchLocateCalls>(pool, source, columns);
    }
    case LoadMode::kNestedBatch:
      return std::make_unique<NestedBatchCalls>(pool, source);
    default:
      return std::make_unique<UnaryLocateCalls>(pool, source);
  }
}

void Run(const LoadOptions& options, ClientPool& pool, QuerySource& source,
         RunBudget& budget, RunRecorder& recorder) {
  if (options.mode == LoadMode::kStream) {
    RunStreams(pool, source, options.concurrency, options.window, budget,
               recorder);
    return;
  }
  const std::unique_ptr<CallStarter> calls =
      MakeCallStarter(options, pool, source);
  if (options.rate > 0) {
    RunOpenLoop(*calls, options.points_per_call(), options.rate, options.seed,
                budget, recorder);
  } else {
    RunClosedLoop(*calls, options.points_per_call(), options.concurrency,
                  budget, recorder);
  }
}

// Generated workloads are placed in the dataset's bounding box, which only
// the server knows.
bool ReadDatasetBox(LocatorClient& client, BoundingBox* box) {
  v1::GetStatsResponse stats;
  const grpc::Status status = client.GetStats(&stats);
  if (!status.ok()) {
    std::cerr << "error: reading the dataset's bounding box: "
              << DescribeRpcError(status) << "\n";
    return false;
  }
  const v1::BoundingBox& bounds = stats.dataset().bounding_box();
  *box = BoundingBox{bounds.min_x(), bounds.min_y(), bounds.max_x(),
                     bounds.max_y()};
  return true;
}

int Main(int argc, char** argv) {
  LoadOptions options;
  Status status = ParseLoadOptions(
      std::vector<std::string>(argv + 1, argv + argc), &options);
  if (!status.ok()) {
    std::cerr << "error: " << status.message() << "\n\n" << LoadUsage();
    return kExitUsage;
  }
  if (options.help) {
    std::cout << LoadUsage();
    return kExitOk;
  }

  // Opened first, so that a bad path fails before any call.
  std::ofstream plot;
  if (!options.plot_path.empty()) {
    plot.open(options.plot_path);
    if (!plot) {
      std::cerr << "error: cannot write --plot " << options.plot_path << "\n";
      return kExitUsage;
    }
  }

  // Installed before the first call, so that an early SIGUSR1 does not
  // kill the process (its default action).
  const std::atomic<uint32_t>* phase_counter =
      options.phase_signal ? &InstallPhaseSignal() : nullptr;

  ClientPool pool(options.channel, options.channels,
                  std::chrono::milliseconds(options.deadline_ms),
                  options.scope);
  if (options.route) {
    if (grpc::Status routed = pool.RouteByTopology(); !routed.ok()) {
      std::cerr << "error: --route: " << DescribeRpcError(routed) << "\n";
      return kExitCallsFailed;
    }
  }
  BoundingBox box;
  if (!QuerySource::IsReplay(options.workload) &&
      !ReadDatasetBox(pool.client(0), &box)) {
    return kExitCallsFailed;
  }
  std::unique_ptr<QuerySource> source;
  status = QuerySource::Create(options.workload, box, options.seed, &source);
  if (!status.ok()) {
    std::cerr << "error: " << status.message() << "\n";
    return kExitUsage;
  }

  const LoadClock::time_point start = LoadClock::now();
  RecorderOptions recording;
  recording.cost_window = options.cost_window;
  recording.origin = start;
  recording.timeline_slice = std::chrono::duration_cast<LoadClock::duration>(
      std::chrono::duration<double>(options.timeline_seconds));
  recording.phase_counter = phase_counter;
  RunRecorder recorder(recording);
  RunBudget budget(options.length, start);
  {
    ProgressLine progress(recorder);
    Run(options, pool, *source, budget, recorder);
  }
  LoadReport report{recorder.Finish()};
  if (report.totals.calls > 0) {
    report.measured_seconds =
        std::chrono::duration<double>(report.totals.last_end -
                                      budget.measure_start())
            .count();
  }
  std::cout << (options.format == ReportFormat::kJson
                    ? FormatReportJson(options, report)
                    : FormatReportText(options, report));
  if (plot.is_open()) {
    plot << RenderLoadPlot(DescribeRun(options), report.totals);
    if (!plot.flush()) {
      std::cerr << "error: writing --plot " << options.plot_path << "\n";
      return kExitCallsFailed;
    }
  }
  return report.failed_calls() > 0 ? kExitCallsFailed : kExitOk;
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) {
  // Outlives every gRPC object Main() makes (see grpc_lifetime.h).
  const locator::GrpcLifetime grpc;
  return locator::Main(argc, argv);
}
