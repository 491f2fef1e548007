#include "server/config/server_config.h"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <limits>

#include "common/flags/flag_set.h"
#include "common/status_macros.h"
#include "server/config/engine_flags.h"
#include "server/config/http_flags.h"
#include "server/datasets/shard_tiles.h"
#include "server/datasets/tile_set_source.h"

namespace locator {
namespace {

constexpr char kDatasetHelp[] =
    "repeatable: a dataset to serve, named NAME (requests name "
    "it in their `dataset` field); the first given is the default dataset, "
    "and a bare SPEC (first only) is named \"default\". SPEC: FILE (CSV/XYZ, "
    ".node, .poly, .ele, .off, POINTS+CONSTRAINTS.wkt) | uniform:N[:SEED] | "
    "clusters:N:K[:SEED] | GIS.gpkg|.shp|.geojson|.fgb[?OPTIONS] | "
    "ogr:SOURCE[?OPTIONS] (OPTIONS: layer=, z=, where=, breaklines=, "
    "domain=, a_srs=, oo=, driver=) | DEM.tif|.vrt|.asc|.img|.hgt...[?OPTIONS] "
    "| raster:SOURCE[?OPTIONS] (band=, a_srs=, driver=) | "
    "CLOUD.las[?OPTIONS] | las:PATH[?OPTIONS] (classes=2,9, "
    "returns=all|first|last); any SPEC also takes ?max_error=E (a TIN "
    "within E of every sample; a raster always is one, E=0 by default) and "
    "max_points=N";

// Declares the flags both servers take, into `config`.
void AddServingFlags(ServingConfig* config, TransportFiles* files,
                     FlagSet* flags) {
  flags->Add("listen",
             flag::Parsed([config](std::string_view text) {
               return ParseListenAddress(text, &config->listen_host,
                                         &config->listen_port);
             })
                 .Shape("HOST:PORT")
                 .Default(config->ListenAddress()),
             "where to serve; port 0 lets the OS pick (the chosen port is "
             "printed)");
  // gRPC takes the limit as an int.
  flags->Add("max-message-bytes",
             flag::Bytes(&config->max_message_bytes, 4096,
                         std::numeric_limits<int>::max()),
             "gRPC message size limit");
  flags->Add("threads", flag::Count(&config->threads, 1, 256),
             "threads that locate one large batch together");
  // A protobuf repeated field holds at most INT_MAX elements: of points,
  // of samples, of grid cells.
  flags->Add("max-batch-points",
             flag::Count(&config->max_batch_points, 1,
                         std::numeric_limits<int>::max()),
             "larger LocateBatch requests fail with RESOURCE_EXHAUSTED");
  flags->Add("max-profile-crossings",
             flag::Count(&config->max_profile_crossings, 1, uint64_t{1} << 40),
             "a Profile whose line crosses more triangle edges (holes "
             "included) fails with RESOURCE_EXHAUSTED");
  flags->Add("max-profile-samples",
             flag::Count(&config->max_profile_samples, 1,
                         std::numeric_limits<int>::max()),
             "a Profile asking for more evenly spaced samples fails with "
             "RESOURCE_EXHAUSTED");
  flags->Add(
      "max-grid-cells",
      flag::Count(&config->max_grid_cells, 1, std::numeric_limits<int>::max()),
      "a Grid of more cells (width x height) fails with "
      "RESOURCE_EXHAUSTED");
  AddTransportFlags(&config->transport, files, flags);
}

// Runs `flags` over the command line; fills `help` if it was asked for.
Status ParseCommandLine(int argc, const char* const argv[], FlagSet* flags,
                        std::string* help) {
  help->clear();
  Status status = flags->Parse(argc, argv);
  if (status.ok() && flags->help_requested()) *help = flags->Help();
  return status;
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

namespace {

// --tiles needs a tile-set dataset to select from, --route its --shards;
// the --shard-tls flags are for --route.
Status CheckShardFlags(const ServerConfig& config,
                       const ChannelSecurityFlags& shard_tls) {
  if (!config.route && shard_tls.AnyTls()) {
    return Status::InvalidArgument("--shard-tls flags are for --route");
  }
  if (!config.tiles.empty()) {
    RETURN_IF_ERROR(ShardTiles::CheckSelector(config.tiles));
    const bool any_tile_set = std::any_of(
        config.datasets.begin(), config.datasets.end(),
        [](const DatasetConfig& d) { return IsTileSetSpec(d.spec); });
    if (!any_tile_set) {
      return FlagError("tiles", config.tiles,
                       "no --dataset is a tile set (DIR/manifest.json)");
    }
  }
  if (config.route && config.shards.empty()) {
    return Status::InvalidArgument("--route needs --shards TARGET,...");
  }
  if (!config.route && !config.shards.empty()) {
    return Status::InvalidArgument("--shards is for --route");
  }
  for (const std::string& target : config.shards) {
    if (target.empty()) return FlagError("shards", "", "an empty target");
  }
  return Status::OK();
}

}  // namespace

Status ParseServerConfig(int argc, const char* const argv[],
                         ServerConfig* config, std::string* help) {
  *config = ServerConfig();
  config->engine.tuning.background = true;
  std::vector<std::string> datasets;
  for (const DatasetConfig& dataset : config->datasets) {
    datasets.push_back(dataset.spec);
  }
  TransportFiles transport_files;
  AccessFiles access_files;
  FlagSet flags("Usage: locatord [flags]");
  flags.Add("dataset", flag::Repeated(&datasets).Shape("[NAME=]SPEC"),
            kDatasetHelp);
  flags.Add("max-dataset-points",
            flag::Count(&config->dataset_limits.max_points, 3,
                        std::numeric_limits<uint32_t>::max()),
            "points all datasets together may hold: a dataset that would take "
            "the total beyond it fails before it is triangulated. The default "
            "is what 80% of this machine's memory holds at ~350 bytes per "
            "point (a build's peak)");
  flags.Add("reload-dir", flag::Text(&config->reload_dir).Shape("DIR"),
            "a Reload RPC may also load generator specs and the files inside "
            "this directory (resolved; no escape by .. or symlinks); "
            "everything else but a dataset's own spec is PERMISSION_DENIED; "
            "empty = only those");
  flags.Add("tiles", flag::Text(&config->tiles).Shape("SELECTOR"),
            "serve only these tiles of the tile-set datasets: K/N (the K-th, "
            "from 0, of N contiguous parts) or tiles and ranges (0-9,12); "
            "locates elsewhere are FAILED_PRECONDITION, GetTopology tells "
            "clients which tiles this shard serves; empty = all");
  flags.Add("route", flag::Switch(&config->route),
            "run as a stateless router: forward Locate and LocateBatch to "
            "the shard serving each point (GetTopology of --shards) and "
            "other calls to a shard; serves no dataset itself");
  flags.Add("shards", flag::Texts(&config->shards).Shape("TARGET,..."),
            "with --route: the gRPC targets of the shards, one per shard "
            "(a target may resolve to several replicas: dns:///NAME:PORT)");
  ChannelSecurityFlags shard_tls;
  AddChannelTlsFlags("shard-", &shard_tls, &flags);
  AddServingFlags(&config->serving, &transport_files, &flags);
  AddEngineFlags(config, &flags);
  AddHttpFlags(config, &flags);
  AddAccessFlags(&config->access, &access_files, &flags);
  flags.Add("log-level", flag::Choice(&config->log_level, LogLevelWords()),
            "the least severe lines of the log written: errors, warnings "
            "(a file ignored, a reload failed), info (startup, datasets, "
            "signals, --stats-interval-s) or debug (each timed re-tune)");

  Status status = ParseCommandLine(argc, argv, &flags, help);
  if (!status.ok() || !help->empty()) return status;
  status = ParseDatasetFlags(datasets, &config->datasets);
  if (status.ok() && !config->reload_dir.empty()) {
    std::error_code error;
    if (!std::filesystem::is_directory(config->reload_dir, error)) {
      status = FlagError("reload-dir", config->reload_dir, "not a directory");
    }
  }
  if (status.ok()) status = CheckShardFlags(*config, shard_tls);
  if (status.ok()) {
    status = LoadChannelSecurity(shard_tls, &config->shard_security, "shard-");
  }
  if (status.ok()) status = CheckEngineFlags(*config);
  if (status.ok()) status = CheckHttpFlags(*config);
  if (status.ok()) {
    status = ReadTransportFiles(transport_files, &config->serving.transport);
  }
  if (status.ok()) status = ReadAccessFiles(access_files, &config->access);
  return status;
}

Status ParseNoopServerConfig(int argc, const char* const argv[],
                             ServingConfig* config, std::string* help) {
  *config = ServingConfig();
  TransportFiles files;
  FlagSet flags("Usage: locator-noop-server [flags]");
  AddServingFlags(config, &files, &flags);
  Status status = ParseCommandLine(argc, argv, &flags, help);
  if (!status.ok() || !help->empty()) return status;
  return ReadTransportFiles(files, &config->transport);
}

}  // namespace locator
