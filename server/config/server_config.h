// Command-line configuration of locatord and locator-noop-server, declared
// once per flag on a FlagSet (common/flags/flag_set.h). Every flag value is
// validated here, so a bad value fails at startup with a message naming the
// flag and the accepted form (the binaries then exit 2, through
// ExitCodeForFlags).
//
// Thread-safety: free functions over plain values.

#ifndef LOCATOR_SERVER_SERVER_CONFIG_H_
#define LOCATOR_SERVER_SERVER_CONFIG_H_

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "common/channel_security.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "locator/status.h"
#include "server/config/dataset_flag.h"
#include "server/config/security_config.h"
#include "server/config/server_log.h"

namespace locator {

// Flags both binaries share: where and how the gRPC server serves.
struct ServingConfig {
  // --listen HOST:PORT; port 0 lets the OS pick one.
  std::string listen_host = "127.0.0.1";
  int listen_port = 50051;
  // --max-message-bytes: the gRPC send and receive limit.
  size_t max_message_bytes = size_t{64} << 20;
  // --threads: threads that locate one large batch together.
  size_t threads = std::max(1u, std::thread::hardware_concurrency());
  // --max-batch-points: larger LocateBatch requests get RESOURCE_EXHAUSTED.
  size_t max_batch_points = 1'000'000;
  // --max-profile-crossings: a Profile whose line crosses more triangle
  // edges gets RESOURCE_EXHAUSTED.
  uint64_t max_profile_crossings = 1'000'000;
  // --max-profile-samples: a Profile asking for more samples gets
  // RESOURCE_EXHAUSTED. A sample is ~50 bytes of reply (~150 in JSON), so
  // the default's reply stays far inside the default message limit.
  uint32_t max_profile_samples = 100'000;
  // --max-grid-cells: a Grid of more cells gets RESOURCE_EXHAUSTED.
  uint64_t max_grid_cells = uint64_t{1} << 24;
  // TLS, connection limits, keepalive and the default deadline.
  TransportConfig transport;

  // "HOST:PORT" as given to --listen.
  std::string ListenAddress() const;
};

// The points whose triangulation this machine's memory holds: 80% of its
// physical memory at kPeakBytesPerPoint, the resident peak of a build
// (CGAL's triangulation and the serving mesh derived from it; 3.4 GB for
// uniform:10000000); at least 10^6. The default of --max-dataset-points.
inline constexpr size_t kPeakBytesPerPoint = 350;
size_t PointsThisMachineHolds();

// locatord's flags.
struct ServerConfig {
  ServingConfig serving;
  // --dataset [NAME=]SPEC, repeatable, in flag order (the first is the
  // default dataset; see DatasetConfig): a file path, generator spec or OGR
  // source each (see LoadServedDataset). Never empty.
  std::vector<DatasetConfig> datasets = {{.spec = "uniform:1000000:1"}};
  // --max-dataset-points: the points all datasets together may hold; one
  // that would take the total beyond it fails before it is triangulated.
  DatasetLimits dataset_limits{.max_points = PointsThisMachineHolds()};
  // --reload-dir: a Reload RPC may load generator specs and the files inside
  // this directory besides a dataset's own spec (see ReloadPolicy). Empty:
  // only those.
  std::string reload_dir;
  // --token-file, --admin-token-file, --redact.
  AccessConfig access;
  // --strategy, --grid, --warmup, --retune-every, --budget, --state-dir,
  // --mesh-cache; the server always re-tunes in the background.
  EngineOptions engine;
  // --stats-interval-s: period of the stats log line; 0 = off.
  double stats_interval_s = 0;
  // --retune-interval-s: period of time-based re-tunes; 0 = off.
  double retune_interval_s = 0;
  // --http-listen HOST:PORT of the metrics and status page server; port 0
  // lets the OS pick. Off (empty host) by default.
  std::string http_host;
  int http_port = 0;
  // --http-max-body-bytes: larger HTTP request bodies get 413.
  size_t http_max_body_bytes = size_t{16} << 20;
  // --http-cors-origin, repeatable: the exact origins (scheme://host[:port])
  // whose pages may call the HTTP server; empty: CORS is off.
  std::vector<std::string> http_cors_origins;
  // --http-max-grid-cells: an HTTP :grid of more cells gets
  // RESOURCE_EXHAUSTED (its answer is one JSON text, ~20 bytes per cell).
  uint64_t http_max_grid_cells = uint64_t{1} << 20;
  // HTTP connections open at once (not a flag), and
  // --http-max-connections-per-address: those one client address may hold
  // open; more get 503.
  size_t http_max_connections = 512;
  size_t http_max_connections_per_address = 64;
  // --http-max-waiting-calls: HTTP API calls that may wait for a thread in
  // each lane (cheap, expensive); more get 503.
  size_t http_max_waiting_calls = 64;
  // --http-public-status: /api/stats and /api/edges answer without a
  // token even when tokens are required.
  bool http_public_status = false;
  // --tiles SELECTOR: the tiles of its tile-set datasets this server
  // serves (ShardTiles::Select); empty: all of them.
  std::string tiles;
  // --route: run as a stateless router forwarding to --shards, serving no
  // dataset of its own.
  bool route = false;
  // --shards TARGET,...: the gRPC targets of the shards a router forwards
  // to, one per shard.
  std::vector<std::string> shards;
  // --shard-tls, --shard-tls-ca, --shard-tls-cert, --shard-tls-key,
  // --shard-tls-server-name: how a router's channels to its shards are
  // secured (plaintext by default). A caller's token goes on as it came.
  ChannelSecurity shard_security;
  // --log-level: the least severe log lines written (error, warning, info,
  // debug).
  LogLevel log_level = LogLevel::kInfo;

  bool http_enabled() const { return !http_host.empty(); }
};

// Sets `config` to the defaults, then parses locatord's command line into
// it, reading the token and PEM files the flags name. With --help, sets
// `help` to the usage text instead (empty otherwise). InvalidArgument naming
// the flag otherwise.
Status ParseServerConfig(int argc, const char* const argv[],
                         ServerConfig* config, std::string* help);

// The same for locator-noop-server, which takes the serving flags only.
Status ParseNoopServerConfig(int argc, const char* const argv[],
                             ServingConfig* config, std::string* help);

// Parses "HOST:PORT" (the port after the last ':', 0..65535).
Status ParseListenAddress(std::string_view text, std::string* host, int* port);

}  // namespace locator

#endif  // LOCATOR_SERVER_SERVER_CONFIG_H_
