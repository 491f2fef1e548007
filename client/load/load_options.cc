#include "client/load/load_options.h"

#include <cmath>

#include "client/load/query_source.h"
#include "client/points_reader.h"
#include "common/flags/flag_set.h"
#include "common/text_fields.h"

namespace locator {
namespace {

constexpr char kUsageHead[] =
    R"(usage: locator-load [flags]

Drives a locator server with a bounded load and reports throughput, latency
percentiles, errors by status code and the server's mean cost per window of
queries. Exit code: 0 when every call succeeded, 1 when any call failed (the
report still prints) or the --plot file could not be written, 2 for a usage
error.
)";

constexpr double kMinTimelineSeconds = 0.1;

// The flags ParseLoadOptions reads once the whole line is known.
struct LaterFlags {
  std::string warmup = "0";  // seconds or queries, by --duration/--queries
  double duration = 10;
  uint64_t queries = 0;
  ChannelSecurityFlags security;
};

// Declares every flag of locator-load on `flags`, into `options` and
// `later`.
void AddLoadFlags(LoadOptions* options, LaterFlags* later, FlagSet* flags) {
  constexpr uint64_t kNoMax = flag::kMaxOf<int64_t>;
  flags->Add("target", flag::Text(&options->channel.target).Shape("HOST:PORT"),
             "server address");
  flags->Add(
      "mode",
      flag::Choice(&options->mode, {{"unary", LoadMode::kUnary},
                                    {"batch", LoadMode::kBatch},
                                    {"stream", LoadMode::kStream},
                                    {"nested-batch", LoadMode::kNestedBatch}}),
      "how queries are sent (nested-batch: the bench service of "
      "locator-noop-server)");
  flags->Add("workload", flag::Text(&options->workload).Shape("WORKLOAD"),
             "uniform | 1-cluster | 3-cluster | d-cluster | x-cluster | mixed "
             "| drift (in the dataset's bounding box) | file:PATH (replay x,y "
             "rows, cycled)");
  flags->Add("dataset", flag::Text(&options->scope.dataset).Shape("NAME"),
             "the server's dataset to query (default: its default dataset)");
  flags->Add("crs", flag::Text(&options->scope.crs).Shape("CRS"),
             "the CRS of the queries of a file: workload (EPSG:4326, WKT or a "
             "PROJ string; default: the dataset's own coordinates)");
  flags->Add("seed", flag::Count(&options->seed, 0, kNoMax),
             "seed of the generated workload and of the arrival schedule");
  flags->Add("concurrency", flag::Count(&options->concurrency, 1, kNoMax),
             "calls (batches, streams) in flight in a closed loop");
  flags->Add("rate", flag::Number(&options->rate, 0),
             "open loop: Poisson arrivals at this many calls/s (0: closed "
             "loop; not with --mode stream)");
  flags->Add("batch-size", flag::Count(&options->batch_size, 1, kNoMax),
             "points per call of batch and nested-batch");
  flags->Add("all-columns", flag::Switch(&options->all_columns),
             "batch: also ask for vertex ids, barycentric coordinates and "
             "values, as nested-batch answers carry them");
  flags->Add("window", flag::Count(&options->window, 1, kNoMax),
             "stream: requests in flight per stream");
  flags->Add("channels", flag::Count(&options->channels, 1, kNoMax),
             "channels (TCP connections) to spread calls over");
  flags->Add("duration", flag::Seconds(&later->duration, 0, /*above=*/true),
             "measure for this many seconds");
  flags->Add("queries", flag::Count(&later->queries, 1, kNoMax).Default(""),
             "measure this many queries (points) instead");
  flags->Add("warmup", flag::Text(&later->warmup).Shape("SECONDS|N"),
             "unmeasured warm-up first: seconds with --duration, queries with "
             "--queries");
  flags->Add("time-limit",
             flag::Seconds(&options->length.time_limit_seconds, 0,
                           /*above=*/true),
             "seconds after which a --queries run stops anyway");
  flags->Add("deadline-ms", flag::Count(&options->deadline_ms, 1, kNoMax),
             "deadline of every call, in milliseconds");
  flags->Add("retry", flag::Switch(&options->channel.retry_unavailable),
             "retry calls that fail with UNAVAILABLE, with backoff");
  flags->Add("route", flag::Switch(&options->route),
             "send unary and batch locates straight to the shards of a tiled "
             "dataset, by GetTopology of --target (a router or a shard "
             "knowing all of them), splitting batches by shard");
  flags->Add("cost-window", flag::Count(&options->cost_window, 1, kNoMax),
             "queries per window of the server's mean cost");
  flags->Add("format",
             flag::Choice(&options->format, {{"text", ReportFormat::kText},
                                             {"json", ReportFormat::kJson}}),
             "the report: text, or json (one summary object)");
  // Each slice holds a 16 KiB histogram: bound how many a run can make.
  flags->Add("timeline-s",
             flag::Seconds(&options->timeline_seconds, kMinTimelineSeconds),
             "seconds per slice of the timeline (JSON report, --plot)");
  flags->Add("plot", flag::Text(&options->plot_path).Shape("FILE"),
             "write latency (p50, p99) and server cost over time to this SVG "
             "file");
  flags->Add("phase-signal", flag::Switch(&options->phase_signal),
             "each SIGUSR1 starts a new phase; the report breaks calls, "
             "failures and latency down by phase");
  AddChannelSecurityFlags(&later->security, flags);
}

// Fills `length` from --duration / --queries / --warmup.
Status SetRunLength(const LaterFlags& later, const FlagSet& flags,
                    RunLength* length) {
  if (flags.Given("duration") && flags.Given("queries")) {
    return Status::InvalidArgument("give --duration or --queries, not both");
  }
  double warmup = 0;
  if (!ParseDouble(later.warmup, &warmup) || !(warmup >= 0) ||
      !std::isfinite(warmup)) {
    return FlagError("warmup", later.warmup, "must be a number >= 0");
  }
  if (flags.Given("queries")) {
    if (warmup != std::floor(warmup)) {
      return FlagError("warmup", later.warmup,
                       "with --queries, --warmup counts queries: a whole "
                       "number");
    }
    length->measured_queries = later.queries;
    length->warmup_queries = static_cast<uint64_t>(warmup);
    return Status::OK();
  }
  length->measured_seconds = later.duration;
  length->warmup_seconds = warmup;
  return Status::OK();
}

// The checks that need several flags.
Status CheckLoadOptions(const LoadOptions& options) {
  if (Status status = QuerySource::Validate(options.workload); !status.ok()) {
    return status;
  }
  if (!options.scope.crs.empty() && !QuerySource::IsReplay(options.workload)) {
    return Status::InvalidArgument(
        "--crs needs a --workload file:PATH: generated workloads lie in the "
        "dataset's bounding box, in its own coordinates");
  }
  if (options.mode == LoadMode::kNestedBatch &&
      (!options.scope.dataset.empty() || !options.scope.crs.empty())) {
    return Status::InvalidArgument(
        "--dataset and --crs are for the Locator service; nested-batch "
        "calls the bench service, which has neither");
  }
  if (options.rate > 0 && options.mode == LoadMode::kStream) {
    return Status::InvalidArgument(
        "--rate paces calls; streams have no open-loop mode");
  }
  return Status::OK();
}

}  // namespace

size_t LoadOptions::points_per_call() const {
  return mode == LoadMode::kBatch || mode == LoadMode::kNestedBatch ? batch_size
                                                                    : 1;
}

std::string_view LoadModeName(LoadMode mode) {
  switch (mode) {
    case LoadMode::kUnary:
      return "unary";
    case LoadMode::kBatch:
      return "batch";
    case LoadMode::kStream:
      return "stream";
    case LoadMode::kNestedBatch:
      return "nested-batch";
  }
  return "unary";
}

Status ParseLoadOptions(const std::vector<std::string>& args,
                        LoadOptions* options) {
  *options = LoadOptions();
  LaterFlags later;
  FlagSet flags(kUsageHead);
  AddLoadFlags(options, &later, &flags);
  Status status = flags.Parse(args);
  options->help = flags.help_requested();
  if (!status.ok() || options->help) return status;
  status = CheckLoadOptions(*options);
  if (status.ok()) status = SetRunLength(later, flags, &options->length);
  if (status.ok()) {
    status = LoadChannelSecurity(later.security, &options->channel.security);
  }
  return status;
}

std::string LoadUsage() {
  LoadOptions options;
  LaterFlags later;
  FlagSet flags(kUsageHead);
  AddLoadFlags(&options, &later, &flags);
  return flags.Help();
}

}  // namespace locator
