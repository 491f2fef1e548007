// LoadOptions: what a `locator-load` run does, parsed from its command line.
//
// Thread-safety: plain values and a free parsing function.

#ifndef LOCATOR_CLIENT_LOAD_LOAD_OPTIONS_H_
#define LOCATOR_CLIENT_LOAD_LOAD_OPTIONS_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "client/load/run_budget.h"
#include "client/locator_client.h"
#include "locator/status.h"

namespace locator {

enum class LoadMode {
  kUnary,        // Locate, one point per call
  kBatch,        // LocateBatch, --batch-size points per call
  kStream,       // LocateStream, --window requests in flight per stream
  kNestedBatch,  // the bench service's LocateNested, --batch-size per call
};

enum class ReportFormat { kText, kJson };

struct LoadOptions {
  ChannelOptions channel;
  // --route: Locate and LocateBatch go straight to the shards, by the
  // target's GetTopology.
  bool route = false;
  size_t channels = 2;
  LoadMode mode = LoadMode::kUnary;
  // A workload name or "file:PATH" (client/load/query_source.h).
  std::string workload = "uniform";
  // The dataset every call goes to and the CRS of the queries (only with a
  // file: workload; generated ones are in the dataset's own coordinates).
  RequestScope scope;
  uint64_t seed = 1;
  // Calls (batches, streams) in flight in a closed-loop run.
  size_t concurrency = 64;
  // Calls per second of an open-loop run; 0 for a closed loop.
  double rate = 0;
  size_t batch_size = 10'000;
  size_t window = 16;
  // Ask LocateBatch for every optional column, as nested batches carry them.
  bool all_columns = false;
  RunLength length;
  int64_t deadline_ms = 5000;
  uint64_t cost_window = 500;
  ReportFormat format = ReportFormat::kText;
  // Length of a slice of the report's timeline, in seconds.
  double timeline_seconds = 1;
  // Write the timeline as an SVG chart to this file (none when empty).
  std::string plot_path;
  // SIGUSR1 starts a new phase of the run (phase_signal.h).
  bool phase_signal = false;
  // --help was given: print LoadUsage() and do nothing else.
  bool help = false;

  // Points each call (or stream request) locates.
  size_t points_per_call() const;
};

// "unary", "batch", "stream", "nested-batch".
std::string_view LoadModeName(LoadMode mode);

// Parses the arguments after the program name; InvalidArgument naming the
// bad flag or value otherwise.
Status ParseLoadOptions(const std::vector<std::string>& args,
                        LoadOptions* options);

// The --help text.
std::string LoadUsage();

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_LOAD_OPTIONS_H_
