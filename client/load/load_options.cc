#include "client/load/load_options.h"

#include <boost/program_options.hpp>
#include <cmath>
#include <sstream>

#include "client/load/query_source.h"
#include "client/points_reader.h"

namespace po = boost::program_options;

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

// The flags as parsed, before they are checked and converted. Counts are
// signed so that a negative value is caught rather than wrapped.
struct RawFlags {
  std::string mode = "unary";
  std::string format = "text";
  std::string warmup = "0";
  double duration = 0;
  int64_t queries = 0;
  int64_t channels = 2;
  int64_t concurrency = 64;
  int64_t batch_size = 10'000;
  int64_t window = 16;
  int64_t cost_window = 500;
  int64_t seed = 1;
  ChannelSecurityFlags security;
};

po::options_description Flags(LoadOptions& options, RawFlags& raw) {
  po::options_description flags("flags");
  flags.add_options()              //
      ("help", "print this help")  //
      ("target",
       po::value(&options.channel.target)
           ->default_value(options.channel.target),
       "server address HOST:PORT")  //
      ("mode", po::value(&raw.mode)->default_value(raw.mode),
       "unary | batch | stream | nested-batch (the bench service of "
       "locator-noop-server)")  //
      ("workload",
       po::value(&options.workload)->default_value(options.workload),
       "uniform | 1-cluster | 3-cluster | d-cluster | x-cluster | mixed | "
       "drift (in the dataset's bounding box) | file:PATH (replay x,y rows, "
       "cycled)")  //
      ("dataset", po::value(&options.scope.dataset),
       "the server's dataset to query (default: its default dataset)")  //
      ("crs", po::value(&options.scope.crs),
       "the CRS of the queries of a file: workload (EPSG:4326, WKT or a "
       "PROJ string; default: the dataset's own coordinates)")  //
      ("seed", po::value(&raw.seed)->default_value(raw.seed),
       "seed of the generated workload and of the arrival schedule")  //
      ("concurrency",
       po::value(&raw.concurrency)->default_value(raw.concurrency),
       "calls (batches, streams) in flight in a closed loop")  //
      ("rate", po::value(&options.rate)->default_value(options.rate),
       "open loop: Poisson arrivals at this many calls/s (0: closed loop; "
       "not with --mode stream)")  //
      ("batch-size", po::value(&raw.batch_size)->default_value(raw.batch_size),
       "points per call of batch and nested-batch")  //
      ("all-columns", po::bool_switch(&options.all_columns),
       "batch: also ask for vertex ids, barycentric coordinates and values, "
       "as nested-batch answers carry them")  //
      ("window", po::value(&raw.window)->default_value(raw.window),
       "stream: requests in flight per stream")  //
      ("channels", po::value(&raw.channels)->default_value(raw.channels),
       "channels (TCP connections) to spread calls over")  //
      ("duration", po::value(&raw.duration),
       "measure for this many seconds (default 10)")  //
      ("queries", po::value(&raw.queries),
       "measure this many queries (points) instead")  //
      ("warmup", po::value(&raw.warmup)->default_value(raw.warmup),
       "unmeasured warm-up first: seconds with --duration, queries with "
       "--queries")  //
      ("time-limit",
       po::value(&options.length.time_limit_seconds)
           ->default_value(options.length.time_limit_seconds),
       "seconds after which a --queries run stops anyway")  //
      ("deadline-ms",
       po::value(&options.deadline_ms)->default_value(options.deadline_ms),
       "deadline of every call, in milliseconds")  //
      ("retry", po::bool_switch(&options.channel.retry_unavailable),
       "retry calls that fail with UNAVAILABLE, with backoff")  //
      ("cost-window",
       po::value(&raw.cost_window)->default_value(raw.cost_window),
       "queries per window of the server's mean cost")  //
      ("format", po::value(&raw.format)->default_value(raw.format),
       "text | json (one summary object)")  //
      ("timeline-s",
       po::value(&options.timeline_seconds)
           ->default_value(options.timeline_seconds),
       "seconds per slice of the timeline (JSON report, --plot); >= 0.1")  //
      ("plot", po::value(&options.plot_path),
       "write latency (p50, p99) and server cost over time to this SVG "
       "file")  //
      ("phase-signal", po::bool_switch(&options.phase_signal),
       "each SIGUSR1 starts a new phase; the report breaks calls, failures "
       "and latency down by phase");
  AddChannelSecurityFlags(&raw.security, &flags);
  return flags;
}

Status ParseMode(std::string_view name, LoadMode* mode) {
  for (LoadMode m : {LoadMode::kUnary, LoadMode::kBatch, LoadMode::kStream,
                     LoadMode::kNestedBatch}) {
    if (LoadModeName(m) == name) {
      *mode = m;
      return Status::OK();
    }
  }
  return Status::InvalidArgument(
      "--mode must be unary, batch, stream or nested-batch, not '" +
      std::string(name) + "'");
}

// Checks that every count flag is positive; the first that is not is named.
Status CheckPositive(
    std::initializer_list<std::pair<std::string_view, int64_t>> counts) {
  for (const auto& [flag, value] : counts) {
    if (value <= 0) {
      return Status::InvalidArgument("--" + std::string(flag) +
                                     " must be positive, not " +
                                     std::to_string(value));
    }
  }
  return Status::OK();
}

// Fills options->length from --duration / --queries / --warmup.
Status SetRunLength(const RawFlags& raw, bool has_duration, bool has_queries,
                    RunLength* length) {
  if (has_duration && has_queries) {
    return Status::InvalidArgument("give --duration or --queries, not both");
  }
  if (!(length->time_limit_seconds > 0)) {
    return Status::InvalidArgument("--time-limit must be positive");
  }
  double warmup = 0;
  if (!ParseDouble(raw.warmup, &warmup) || !(warmup >= 0) ||
      !std::isfinite(warmup)) {
    return Status::InvalidArgument("--warmup must be a number >= 0, not '" +
                                   raw.warmup + "'");
  }
  if (has_queries) {
    if (raw.queries <= 0) {
      return Status::InvalidArgument("--queries must be positive");
    }
    if (warmup != std::floor(warmup)) {
      return Status::InvalidArgument(
          "with --queries, --warmup counts queries: a whole number");
    }
    length->measured_queries = static_cast<uint64_t>(raw.queries);
    length->warmup_queries = static_cast<uint64_t>(warmup);
    return Status::OK();
  }
  const double duration = has_duration ? raw.duration : 10.0;
  if (!(duration > 0) || !std::isfinite(duration)) {
    return Status::InvalidArgument("--duration must be positive");
  }
  length->measured_seconds = duration;
  length->warmup_seconds = warmup;
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
  RawFlags raw;
  po::variables_map parsed;
  try {
    const po::options_description flags = Flags(*options, raw);
    // Declared so that a stray word is an error rather than ignored.
    const po::positional_options_description no_positionals;
    po::store(po::command_line_parser(args)
                  .options(flags)
                  .positional(no_positionals)
                  .style(po::command_line_style::unix_style ^
                         po::command_line_style::allow_guessing)
                  .run(),
              parsed);
    po::notify(parsed);
  } catch (const po::error& error) {
    return Status::InvalidArgument(error.what());
  }
  options->help = parsed.count("help") > 0;

  Status status = ParseMode(raw.mode, &options->mode);
  if (status.ok()) status = QuerySource::Validate(options->workload);
  if (status.ok() && !options->scope.crs.empty() &&
      !QuerySource::IsReplay(options->workload)) {
    status = Status::InvalidArgument(
        "--crs needs a --workload file:PATH: generated workloads lie in the "
        "dataset's bounding box, in its own coordinates");
  }
  if (status.ok() && options->mode == LoadMode::kNestedBatch &&
      (!options->scope.dataset.empty() || !options->scope.crs.empty())) {
    status = Status::InvalidArgument(
        "--dataset and --crs are for the Locator service; nested-batch "
        "calls the bench service, which has neither");
  }
  if (status.ok()) {
    status = CheckPositive({{"channels", raw.channels},
                            {"concurrency", raw.concurrency},
                            {"batch-size", raw.batch_size},
                            {"window", raw.window},
                            {"cost-window", raw.cost_window},
                            {"deadline-ms", options->deadline_ms}});
  }
  if (status.ok()) {
    status = SetRunLength(raw, parsed.count("duration") > 0,
                          parsed.count("queries") > 0, &options->length);
  }
  if (status.ok()) {
    status = LoadChannelSecurity(raw.security, &options->channel.security);
  }
  if (!status.ok()) return status;
  if (!(options->rate >= 0) || !std::isfinite(options->rate)) {
    return Status::InvalidArgument("--rate must be >= 0");
  }
  if (options->rate > 0 && options->mode == LoadMode::kStream) {
    return Status::InvalidArgument(
        "--rate paces calls; streams have no open-loop mode");
  }
  // Each slice holds a 16 KiB histogram: bound how many a run can make.
  if (!(options->timeline_seconds >= kMinTimelineSeconds) ||
      !std::isfinite(options->timeline_seconds)) {
    return Status::InvalidArgument("--timeline-s must be at least 0.1");
  }
  if (raw.format != "text" && raw.format != "json") {
    return Status::InvalidArgument("--format must be text or json, not '" +
                                   raw.format + "'");
  }
  options->format =
      raw.format == "json" ? ReportFormat::kJson : ReportFormat::kText;
  options->channels = static_cast<size_t>(raw.channels);
  options->concurrency = static_cast<size_t>(raw.concurrency);
  options->batch_size = static_cast<size_t>(raw.batch_size);
  options->window = static_cast<size_t>(raw.window);
  options->cost_window = static_cast<uint64_t>(raw.cost_window);
  options->seed = static_cast<uint64_t>(raw.seed);
  return Status::OK();
}

std::string LoadUsage() {
  LoadOptions options;
  RawFlags raw;
  std::ostringstream usage;
  usage << kUsageHead << Flags(options, raw);
  return usage.str();
}

}  // namespace locator
