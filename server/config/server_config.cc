#include "server/config/server_config.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <boost/program_options.hpp>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

#include "server/config/flag_parsing.h"

namespace locator {
namespace {

namespace po = boost::program_options;

// Flag values as typed. Everything is read as text and validated here, not
// by Boost: its lexical_cast would accept "-1" for an unsigned flag.
struct ServingFlags {
  std::string listen;
  std::string max_message_bytes;
  std::string threads;
  std::string max_batch_points;
  std::string max_profile_crossings;
  std::string max_profile_samples;
  std::string max_grid_cells;
  TransportFlags transport;
};

struct EngineFlags {
  std::string strategy;
  std::string grid;
  std::string warmup;
  std::string retune_every;
  std::string budget;
  std::string stats_interval_s;
  std::string retune_interval_s;
  std::string state_dir;
  std::string mesh_cache;
};

struct HttpFlags {
  std::string listen;
  std::string max_body_bytes;
  std::vector<std::string> cors_origins;
  std::string max_grid_cells;
  std::string max_connections_per_address;
  std::string max_waiting_calls;
  bool public_status = false;
};

void AddServingFlags(const ServingConfig& defaults, ServingFlags* flags,
                     po::options_description* description) {
  description->add_options()(
      "listen",
      po::value(&flags->listen)->default_value(defaults.ListenAddress()),
      "HOST:PORT to serve on; port 0 lets the OS pick (the chosen port is "
      "printed)")(
      "max-message-bytes",
      po::value(&flags->max_message_bytes)
          ->default_value(std::to_string(defaults.max_message_bytes >> 20) +
                          "MiB"),
      "gRPC message size limit (bytes; B, KiB, MiB, GiB suffix)")(
      "threads",
      po::value(&flags->threads)
          ->default_value(std::to_string(defaults.threads)),
      "threads that locate one large batch together")(
      "max-batch-points",
      po::value(&flags->max_batch_points)
          ->default_value(std::to_string(defaults.max_batch_points)),
      "larger LocateBatch requests fail with RESOURCE_EXHAUSTED")(
      "max-profile-crossings",
      po::value(&flags->max_profile_crossings)
          ->default_value(std::to_string(defaults.max_profile_crossings)),
      "a Profile whose line crosses more triangle edges (holes included) "
      "fails with RESOURCE_EXHAUSTED")(
      "max-profile-samples",
      po::value(&flags->max_profile_samples)
          ->default_value(std::to_string(defaults.max_profile_samples)),
      "a Profile asking for more evenly spaced samples fails with "
      "RESOURCE_EXHAUSTED")(
      "max-grid-cells",
      po::value(&flags->max_grid_cells)
          ->default_value(std::to_string(defaults.max_grid_cells)),
      "a Grid of more cells (width x height) fails with "
      "RESOURCE_EXHAUSTED");
  AddTransportFlags(defaults.transport, &flags->transport, description);
}

Status ReadServingFlags(const ServingFlags& flags, ServingConfig* config) {
  if (Status status = ParseListenAddress(flags.listen, &config->listen_host,
                                         &config->listen_port);
      !status.ok()) {
    return FlagError("listen", flags.listen, status.message());
  }
  // gRPC takes the limit as an int.
  if (Status status = ParseByteFlag(
          "max-message-bytes", flags.max_message_bytes, 4096,
          std::numeric_limits<int>::max(), &config->max_message_bytes);
      !status.ok()) {
    return status;
  }
  if (Status status =
          ParseCountAs("threads", flags.threads, 1, 256, &config->threads);
      !status.ok()) {
    return status;
  }
  // A protobuf repeated field holds at most INT_MAX elements.
  if (Status status = ParseCountAs("max-batch-points", flags.max_batch_points,
                                   1, std::numeric_limits<int>::max(),
                                   &config->max_batch_points);
      !status.ok()) {
    return status;
  }
  if (Status status =
          ParseCountAs("max-profile-crossings", flags.max_profile_crossings, 1,
                       uint64_t{1} << 40, &config->max_profile_crossings);
      !status.ok()) {
    return status;
  }
  // A reply holds the samples in one protobuf repeated field.
  if (Status status = ParseCountAs(
          "max-profile-samples", flags.max_profile_samples, 1,
          std::numeric_limits<int>::max(), &config->max_profile_samples);
      !status.ok()) {
    return status;
  }
  // An HTTP :grid answers every cell in one protobuf repeated field.
  if (Status status = ParseCountAs("max-grid-cells", flags.max_grid_cells, 1,
                                   std::numeric_limits<int>::max(),
                                   &config->max_grid_cells);
      !status.ok()) {
    return status;
  }
  return ReadTransportFlags(flags.transport, &config->transport);
}

void AddEngineFlags(const ServerConfig& defaults, EngineFlags* flags,
                    po::options_description* description) {
  const TuningOptions& tuning = defaults.engine.tuning;
  description->add_options()(
      "strategy",
      po::value(&flags->strategy)->default_value(defaults.engine.strategy),
      "walk | jump-and-walk | adaptive-paper | self-tuning")(
      "grid",
      po::value(&flags->grid)->default_value(std::to_string(tuning.grid_size)),
      "query histogram cells per side")(
      "warmup",
      po::value(&flags->warmup)
          ->default_value(std::to_string(tuning.warmup_queries)),
      "adaptive-paper: queries counted before the hot regions are chosen")(
      "retune-every",
      po::value(&flags->retune_every)
          ->default_value(std::to_string(tuning.retune_every)),
      "self-tuning: re-tune after this many queries")(
      "budget",
      po::value(&flags->budget)
          ->default_value(std::to_string(tuning.budget_bytes)),
      "self-tuning: start table memory budget (bytes; B, KiB, MiB, GiB "
      "suffix); 0 = 10% of the triangulation")(
      "stats-interval-s",
      po::value(&flags->stats_interval_s)->default_value("0"),
      "log a stats line this often; 0 = never")(
      "retune-interval-s",
      po::value(&flags->retune_interval_s)->default_value("0"),
      "also re-tune this often; 0 = only by query count")(
      "state-dir", po::value(&flags->state_dir)->default_value(""),
      "self-tuning: directory where the learned tuning persists across "
      "restarts and reloads (a dataset named by NAME=SPEC keeps its files "
      "in DIR/NAME, made if missing); empty = off")(
      "mesh-cache", po::value(&flags->mesh_cache)->default_value(""),
      "directory of serving-mesh files, one per dataset (named by its "
      "fingerprint): a start or reload maps the dataset's file instead of "
      "triangulating, and writes it after triangulating; empty = off");
}

void AddHttpFlags(const ServerConfig& defaults, HttpFlags* flags,
                  po::options_description* description) {
  description->add_options()(
      "http-listen", po::value(&flags->listen)->default_value(""),
      "HOST:PORT for /metrics, the status page, the web example (/web/) and "
      "the HTTP/JSON API (/v1/); port 0 lets the OS pick (the chosen port is "
      "printed); empty = off")(
      "http-max-body-bytes",
      po::value(&flags->max_body_bytes)
          ->default_value(std::to_string(defaults.http_max_body_bytes >> 20) +
                          "MiB"),
      "larger HTTP request bodies get 413 (bytes; B, KiB, MiB, GiB suffix)")(
      "http-cors-origin", po::value(&flags->cors_origins)->composing(),
      "an origin (scheme://host[:port], exact) whose web pages may call the "
      "HTTP server (CORS); repeatable; none = CORS off")(
      "http-max-grid-cells",
      po::value(&flags->max_grid_cells)
          ->default_value(std::to_string(defaults.http_max_grid_cells)),
      "an HTTP :grid of more cells fails with RESOURCE_EXHAUSTED (its answer "
      "is one JSON text of ~20 bytes per cell; gRPC streams up to "
      "--max-grid-cells)")(
      "http-max-connections-per-address",
      po::value(&flags->max_connections_per_address)
          ->default_value(
              std::to_string(defaults.http_max_connections_per_address)),
      "HTTP connections one client address may hold open; more get 503 "
      "(behind a reverse proxy, every client has the proxy's address)")(
      "http-max-waiting-calls",
      po::value(&flags->max_waiting_calls)
          ->default_value(std::to_string(defaults.http_max_waiting_calls)),
      "HTTP API calls that may wait for a thread in each lane (cheap: "
      ":locate and small batches; expensive: :profile, :grid, large "
      "batches); a call finding that many waiting gets 503 with "
      "Retry-After")(
      "http-public-status", po::bool_switch(&flags->public_status),
      "/api/stats and /api/edges answer without a token even with "
      "--token-file (they show the dataset's source and coordinates)");
}

// An exact origin as browsers send it: http(s)://host[:port], nothing after.
Status CheckCorsOrigin(const std::string& origin) {
  const size_t scheme_end = origin.find("://");
  const std::string_view scheme = std::string_view(origin).substr(
      0, scheme_end == std::string::npos ? 0 : scheme_end);
  if (scheme != "http" && scheme != "https") {
    return FlagError("http-cors-origin", origin,
                     "expected http://HOST[:PORT] or https://HOST[:PORT]");
  }
  const std::string_view rest = std::string_view(origin).substr(scheme_end + 3);
  if (rest.empty() || rest.find_first_of("/?#* ") != std::string_view::npos) {
    return FlagError("http-cors-origin", origin,
                     "an origin is scheme://host[:port] exactly, without a "
                     "path or wildcards");
  }
  return Status::OK();
}

Status ReadHttpFlags(const HttpFlags& flags, ServerConfig* config) {
  if (!flags.listen.empty()) {
    if (Status status = ParseListenAddress(flags.listen, &config->http_host,
                                           &config->http_port);
        !status.ok()) {
      return FlagError("http-listen", flags.listen, status.message());
    }
  }
  if (Status status = ParseByteFlag("http-max-body-bytes", flags.max_body_bytes,
                                    1024, std::numeric_limits<uint32_t>::max(),
                                    &config->http_max_body_bytes);
      !status.ok()) {
    return status;
  }
  for (const std::string& origin : flags.cors_origins) {
    if (Status status = CheckCorsOrigin(origin); !status.ok()) return status;
  }
  config->http_cors_origins = flags.cors_origins;
  if (Status status = ParseCountAs("http-max-grid-cells", flags.max_grid_cells,
                                   1, std::numeric_limits<int>::max(),
                                   &config->http_max_grid_cells);
      !status.ok()) {
    return status;
  }
  if (Status status = ParseCountAs("http-max-connections-per-address",
                                   flags.max_connections_per_address, 1,
                                   config->http_max_connections,
                                   &config->http_max_connections_per_address);
      !status.ok()) {
    return status;
  }
  // Each waiting call holds a connection: more could never wait.
  if (Status status = ParseCountAs(
          "http-max-waiting-calls", flags.max_waiting_calls, 1,
          config->http_max_connections, &config->http_max_waiting_calls);
      !status.ok()) {
    return status;
  }
  config->http_public_status = flags.public_status;
  return Status::OK();
}

// The state dir must exist (locatord does not create directories), and only
// the self-tuning strategy has state to keep.
Status ReadStateDir(const EngineFlags& flags, EngineOptions* engine) {
  if (flags.state_dir.empty()) return Status::OK();
  std::error_code error;
  if (!std::filesystem::is_directory(flags.state_dir, error)) {
    return FlagError("state-dir", flags.state_dir, "not a directory");
  }
  if (engine->strategy != "self-tuning") {
    return FlagError("state-dir", flags.state_dir,
                     "only the self-tuning strategy keeps state");
  }
  engine->tuning.state_dir = flags.state_dir;
  return Status::OK();
}

// The mesh cache must be an existing directory (locatord does not create
// directories).
Status ReadMeshCache(const EngineFlags& flags, EngineOptions* engine) {
  if (flags.mesh_cache.empty()) return Status::OK();
  std::error_code error;
  if (!std::filesystem::is_directory(flags.mesh_cache, error)) {
    return FlagError("mesh-cache", flags.mesh_cache, "not a directory");
  }
  engine->mesh_cache_dir = flags.mesh_cache;
  return Status::OK();
}

Status ReadEngineFlags(const EngineFlags& flags, ServerConfig* config) {
  if (Status s = ValidateStrategy(flags.strategy); !s.ok()) {
    return FlagError("strategy", flags.strategy, s.message());
  }
  EngineOptions& engine = config->engine;
  engine.strategy = flags.strategy;
  engine.tuning.background = true;
  Status status = ParseCountAs("grid", flags.grid, 1, kMaxGridSize,
                               &engine.tuning.grid_size);
  if (status.ok()) {
    status = ParseCountAs("warmup", flags.warmup, 1,
                          std::numeric_limits<int64_t>::max(),
                          &engine.tuning.warmup_queries);
  }
  if (status.ok()) {
    status = ParseCountAs("retune-every", flags.retune_every, 1,
                          std::numeric_limits<int64_t>::max(),
                          &engine.tuning.retune_every);
  }
  if (status.ok()) {
    status = ParseByteFlag("budget", flags.budget, 0,
                           std::numeric_limits<int64_t>::max(),
                           &engine.tuning.budget_bytes);
  }
  if (status.ok()) {
    status = ParseSeconds("stats-interval-s", flags.stats_interval_s,
                          &config->stats_interval_s);
  }
  if (status.ok()) {
    status = ParseSeconds("retune-interval-s", flags.retune_interval_s,
                          &config->retune_interval_s);
  }
  if (status.ok()) status = ReadStateDir(flags, &engine);
  if (status.ok()) status = ReadMeshCache(flags, &engine);
  return status;
}

// Runs Boost over `description` (plus --help); fills `help` if asked for.
Status ParseCommandLine(int argc, const char* const argv[],
                        std::string_view program,
                        po::options_description description,
                        std::string* help) {
  help->clear();
  description.add_options()("help", "print this help and exit");
  po::variables_map values;
  try {
    // An empty positional description makes stray arguments an error
    // instead of silently ignored.
    po::store(po::command_line_parser(argc, argv)
                  .options(description)
                  .positional(po::positional_options_description())
                  .run(),
              values);
    po::notify(values);
  } catch (const po::error& error) {
    return Status::InvalidArgument(error.what());
  }
  if (values.count("help") > 0) {
    std::ostringstream text;
    text << "Usage: " << program << " [flags]\n\n" << description << "\n";
    *help = text.str();
  }
  return Status::OK();
}

}  // namespace

size_t PointsThisMachineHolds() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_bytes = sysconf(_SC_PAGE_SIZE);
  constexpr size_t kAtLeast = 1'000'000;
  if (pages <= 0 || page_bytes <= 0) return kAtLeast;
  const double usable = 0.8 * static_cast<double>(pages) * page_bytes;
  return std::max(kAtLeast, static_cast<size_t>(usable / kPeakBytesPerPoint));
}

std::string ServingConfig::ListenAddress() const {
  return listen_host + ":" + std::to_string(listen_port);
}

std::optional<int> ExitCodeForFlags(std::string_view program,
                                    const Status& parsed,
                                    const std::string& help) {
  if (!parsed.ok()) {
    std::cerr << program << ": " << parsed.message() << "\n(see " << program
              << " --help)" << std::endl;
    return 2;
  }
  if (!help.empty()) {
    std::cout << help;
    return 0;
  }
  return std::nullopt;
}

Status ParseListenAddress(std::string_view text, std::string* host, int* port) {
  const size_t colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) {
    return Status::InvalidArgument("expected HOST:PORT");
  }
  const std::string_view port_text = text.substr(colon + 1);
  int value = 0;
  const auto [end, error] = std::from_chars(
      port_text.data(), port_text.data() + port_text.size(), value);
  if (port_text.empty() || error != std::errc() ||
      end != port_text.data() + port_text.size() || value < 0 ||
      value > 65535) {
    return Status::InvalidArgument("the port must be a number in 0..65535");
  }
  *host = std::string(text.substr(0, colon));
  *port = value;
  return Status::OK();
}

Status ParseServerConfig(int argc, const char* const argv[],
                         ServerConfig* config, std::string* help) {
  const ServerConfig defaults;
  std::vector<std::string> datasets;
  std::string max_dataset_points;
  std::string reload_dir;
  ServingFlags serving;
  EngineFlags engine;
  HttpFlags http;
  AccessFlags access;
  po::options_description description("locatord flags");
  description.add_options()(
      "dataset", po::value(&datasets)->composing(),
      "[NAME=]SPEC, repeatable: a dataset to serve, named NAME (requests "
      "name it in their `dataset` field); the first given is the default "
      "dataset, and a bare SPEC (first only) is named \"default\". SPEC: "
      "FILE (CSV/XYZ, .node, .poly, .ele, .off, POINTS+CONSTRAINTS.wkt) | "
      "uniform:N[:SEED] | clusters:N:K[:SEED] | "
      "GIS.gpkg|.shp|.geojson|.fgb[?OPTIONS] | ogr:SOURCE[?OPTIONS] "
      "(OPTIONS: layer=, z=, where=, breaklines=, domain=, a_srs=, oo=, "
      "driver=) | DEM.tif|.vrt|.asc|.img|.hgt...[?OPTIONS] | "
      "raster:SOURCE[?OPTIONS] (band=, a_srs=, driver=) | CLOUD.las[?OPTIONS] "
      "| las:PATH[?OPTIONS] "
      "(classes=2,9, returns=all|first|last); any SPEC also takes "
      "?max_error=E (a TIN within E of every sample; a raster always is "
      "one, E=0 by default) and max_points=N. Default: uniform:1000000:1")(
      "max-dataset-points",
      po::value(&max_dataset_points)
          ->default_value(std::to_string(defaults.dataset_limits.max_points)),
      "points all datasets together may hold: a dataset that would take "
      "the total beyond it fails before it is triangulated. Default: what "
      "80% of this machine's memory holds at ~350 bytes per point (a "
      "build's peak)")(
      "reload-dir", po::value(&reload_dir)->default_value(""),
      "a Reload RPC may also load generator specs and the files inside this "
      "directory (resolved; no escape by .. or symlinks); everything else "
      "but a dataset's own spec is PERMISSION_DENIED; empty = only those");
  AddServingFlags(defaults.serving, &serving, &description);
  AddEngineFlags(defaults, &engine, &description);
  AddHttpFlags(defaults, &http, &description);
  AddAccessFlags(&access, &description);

  Status status = ParseCommandLine(argc, argv, "locatord", description, help);
  if (!status.ok() || !help->empty()) return status;
  if (!datasets.empty()) {
    status = ParseDatasetFlags(datasets, &config->datasets);
    if (!status.ok()) return status;
  }
  std::error_code error;
  if (!reload_dir.empty() &&
      !std::filesystem::is_directory(reload_dir, error)) {
    return FlagError("reload-dir", reload_dir, "not a directory");
  }
  config->reload_dir = reload_dir;
  status = ParseCountAs("max-dataset-points", max_dataset_points, 3,
                        std::numeric_limits<uint32_t>::max(),
                        &config->dataset_limits.max_points);
  if (status.ok()) status = ReadServingFlags(serving, &config->serving);
  if (status.ok()) status = ReadEngineFlags(engine, config);
  if (status.ok()) status = ReadHttpFlags(http, config);
  if (status.ok()) status = ReadAccessFlags(access, &config->access);
  return status;
}

Status ParseNoopServerConfig(int argc, const char* const argv[],
                             ServingConfig* config, std::string* help) {
  ServingFlags serving;
  po::options_description description("locator-noop-server flags");
  AddServingFlags(ServingConfig(), &serving, &description);
  Status status =
      ParseCommandLine(argc, argv, "locator-noop-server", description, help);
  if (!status.ok() || !help->empty()) return status;
  return ReadServingFlags(serving, config);
}

}  // namespace locator
