#include "server/config/server_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace locator {
namespace {

using ::testing::HasSubstr;

// Parses locatord's flags `args` (argv[0] added).
Status Parse(std::vector<std::string> args, ServerConfig* config,
             std::string* help) {
  args.insert(args.begin(), "locatord");
  std::vector<const char*> argv;
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  return ParseServerConfig(static_cast<int>(argv.size()), argv.data(), config,
                           help);
}

Status Parse(std::vector<std::string> args, ServerConfig* config) {
  std::string help;
  return Parse(std::move(args), config, &help);
}

TEST(ServerConfigTest, DefaultsWithoutFlags) {
  ServerConfig config;
  std::string help;
  ASSERT_TRUE(Parse({}, &config, &help).ok());
  EXPECT_EQ(help, "");
  EXPECT_EQ(config.datasets,
            std::vector<DatasetConfig>{{.spec = "uniform:1000000:1"}});
  EXPECT_EQ(config.serving.ListenAddress(), "127.0.0.1:50051");
  EXPECT_EQ(config.serving.max_message_bytes, 64u << 20);
  EXPECT_EQ(config.serving.max_batch_points, 1'000'000u);
  EXPECT_EQ(config.serving.max_profile_samples, 100'000u);
  EXPECT_GE(config.serving.threads, 1u);
  EXPECT_EQ(config.engine.strategy, "self-tuning");
  EXPECT_TRUE(config.engine.tuning.background);
  EXPECT_EQ(config.engine.tuning.budget_bytes, 0u);
  EXPECT_EQ(config.stats_interval_s, 0);
  EXPECT_EQ(config.retune_interval_s, 0);
  EXPECT_EQ(config.engine.tuning.state_dir, "");
  EXPECT_FALSE(config.http_enabled());
  EXPECT_EQ(config.dataset_limits.max_points, PointsThisMachineHolds());
  // 80% of the physical memory at the build's peak bytes per point.
  const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
                        static_cast<double>(sysconf(_SC_PAGE_SIZE));
  EXPECT_NEAR(static_cast<double>(PointsThisMachineHolds()),
              std::max(1e6, 0.8 * memory / kPeakBytesPerPoint), 1.0);
  const TransportConfig& transport = config.serving.transport;
  EXPECT_FALSE(transport.tls.enabled());
  EXPECT_EQ(transport.max_concurrent_streams, 100);
  EXPECT_EQ(transport.keepalive_time_ms, 60'000);
  EXPECT_EQ(transport.keepalive_timeout_ms, 20'000);
  EXPECT_EQ(transport.min_ping_interval_ms, 10'000);
  EXPECT_EQ(transport.max_ping_strikes, 2);
  EXPECT_EQ(transport.default_deadline, std::chrono::seconds(30));
  EXPECT_EQ(config.access.data_token, "");
  EXPECT_EQ(config.access.admin_token, "");
  EXPECT_FALSE(config.access.redact);
}

TEST(ServerConfigTest, LimitFlagsMapToTheConfig) {
  ServerConfig config;
  const Status status =
      Parse({"--max-dataset-points", "1000", "--max-concurrent-streams", "8",
             "--keepalive-time-ms", "5000", "--keepalive-timeout-ms", "1000",
             "--min-ping-interval-ms", "2000", "--max-ping-strikes", "0",
             "--default-deadline-ms", "0", "--redact"},
            &config);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(config.dataset_limits.max_points, 1000u);
  const TransportConfig& transport = config.serving.transport;
  EXPECT_EQ(transport.max_concurrent_streams, 8);
  EXPECT_EQ(transport.keepalive_time_ms, 5000);
  EXPECT_EQ(transport.keepalive_timeout_ms, 1000);
  EXPECT_EQ(transport.min_ping_interval_ms, 2000);
  EXPECT_EQ(transport.max_ping_strikes, 0);
  EXPECT_EQ(transport.default_deadline.count(), 0);
  EXPECT_TRUE(config.access.redact);
}

TEST(ServerConfigTest, EveryFlagMapsToTheConfig) {
  ServerConfig config;
  const Status status = Parse({"--dataset",
                               "clusters:5000:4:2",
                               "--listen",
                               "0.0.0.0:0",
                               "--strategy",
                               "adaptive-paper",
                               "--grid",
                               "16",
                               "--warmup",
                               "300",
                               "--retune-every",
                               "500",
                               "--budget",
                               "64KiB",
                               "--threads",
                               "3",
                               "--max-batch-points",
                               "1000",
                               "--max-profile-samples",
                               "2500",
                               "--max-message-bytes",
                               "8MiB",
                               "--stats-interval-s",
                               "2.5",
                               "--retune-interval-s",
                               "30"},
                              &config);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(config.datasets,
            std::vector<DatasetConfig>{{.spec = "clusters:5000:4:2"}});
  EXPECT_EQ(config.serving.listen_host, "0.0.0.0");
  EXPECT_EQ(config.serving.listen_port, 0);
  EXPECT_EQ(config.engine.strategy, "adaptive-paper");
  EXPECT_EQ(config.engine.tuning.grid_size, 16);
  EXPECT_EQ(config.engine.tuning.warmup_queries, 300u);
  EXPECT_EQ(config.engine.tuning.retune_every, 500u);
  EXPECT_EQ(config.engine.tuning.budget_bytes, 64u * 1024);
  EXPECT_TRUE(config.engine.tuning.background);
  EXPECT_EQ(config.serving.threads, 3u);
  EXPECT_EQ(config.serving.max_batch_points, 1000u);
  EXPECT_EQ(config.serving.max_profile_samples, 2500u);
  EXPECT_EQ(config.serving.max_message_bytes, 8u << 20);
  EXPECT_EQ(config.stats_interval_s, 2.5);
  EXPECT_EQ(config.retune_interval_s, 30);
}

TEST(ServerConfigTest, HelpListsTheFlags) {
  ServerConfig config;
  std::string help;
  ASSERT_TRUE(Parse({"--help"}, &config, &help).ok());
  EXPECT_THAT(help, HasSubstr("Usage: locatord"));
  EXPECT_THAT(help, HasSubstr("--dataset"));
  EXPECT_THAT(help, HasSubstr("--budget"));
  EXPECT_THAT(help, HasSubstr("--retune-interval-s"));
  for (const char* flag :
       {"--tls-cert", "--tls-client-ca", "--token-file", "--admin-token-file",
        "--redact", "--max-concurrent-streams", "--min-ping-interval-ms",
        "--default-deadline-ms", "--max-dataset-points", "--http-listen",
        "--state-dir", "--http-max-body-bytes", "--http-cors-origin",
        "--http-max-grid-cells", "--http-max-connections-per-address",
        "--http-max-waiting-calls", "--http-public-status",
        "--max-profile-samples", "--log-level error|warning|info|debug"}) {
    EXPECT_THAT(help, HasSubstr(flag));
  }
  EXPECT_THAT(help, HasSubstr("--shard-tls-ca FILE"));
  EXPECT_THAT(help, HasSubstr("--shard-tls-server-name NAME"));
}

TEST(ServerConfigTest, BadValuesFailNamingTheFlag) {
  const std::vector<std::vector<std::string>> bad = {
      {"--threads", "0"},
      {"--threads", "-1"},
      {"--threads", "two"},
      {"--grid", "0"},
      {"--retune-every", "0"},
      {"--warmup", "1e3"},
      {"--warmup", "0"},
      {"--budget", "12kb"},
      {"--budget", "-5"},
      {"--budget", "99999999999999999999GiB"},
      {"--max-message-bytes", "100"},
      {"--max-message-bytes", "4GiB"},
      {"--max-batch-points", "0"},
      {"--max-profile-samples", "0"},
      {"--max-profile-samples", "-5"},
      {"--max-profile-samples", "2147483648"},
      {"--stats-interval-s", "-1"},
      {"--retune-interval-s", "nan"},
      {"--listen", "50051"},
      {"--listen", ":50051"},
      {"--listen", "localhost:65536"},
      {"--listen", "localhost:http"},
      {"--http-listen", "8080"},
      {"--http-listen", "localhost:65536"},
      {"--strategy", "fastest"},
      {"--dataset", ""},
      {"--dataset", "terrain="},
      {"--http-max-body-bytes", "100"},
      {"--http-max-body-bytes", "8GiB"},
      {"--http-cors-origin", "example.com"},
      {"--http-cors-origin", "http://example.com/"},
      {"--http-cors-origin", "https://*.example.com"},
      {"--http-cors-origin", "ftp://example.com"},
      {"--http-max-grid-cells", "0"},
      {"--http-max-grid-cells", "3000000000"},
      {"--http-max-grid-cells", "1e6"},
      {"--http-max-connections-per-address", "0"},
      {"--http-max-connections-per-address", "513"},
      {"--http-max-connections-per-address", "many"},
      {"--http-max-waiting-calls", "0"},
      {"--http-max-waiting-calls", "513"},
      {"--http-max-waiting-calls", "-1"},
      {"--max-dataset-points", "2"},
      {"--max-dataset-points", "5000000000"},
      {"--max-concurrent-streams", "0"},
      {"--keepalive-time-ms", "0"},
      {"--keepalive-timeout-ms", "soon"},
      {"--min-ping-interval-ms", "-1"},
      {"--max-ping-strikes", "3000000000"},
      {"--default-deadline-ms", "1.5"},
      {"--tls-cert", "/no/such/cert.pem"},
      {"--tls-client-ca", "/no/such/ca.pem"},
      {"--token-file", "/no/such/token"},
      {"--admin-token-file", "/no/such/token"},
  };
  for (const std::vector<std::string>& args : bad) {
    ServerConfig config;
    const Status status = Parse(args, &config);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << args[0];
    EXPECT_THAT(status.message(), HasSubstr(args[0]));
  }
}

TEST(ServerConfigTest, ShardTlsFlagsAreARoutersAndNameTheirFiles) {
  ServerConfig config;
  ASSERT_TRUE(Parse({"--route", "--shards", "a:1,b:2",
                     "--shard-tls-server-name", "shards.example"},
                    &config)
                  .ok());
  EXPECT_TRUE(config.shard_security.tls);
  EXPECT_EQ(config.shard_security.server_name, "shards.example");
  ASSERT_TRUE(Parse({"--route", "--shards", "a:1"}, &config).ok());
  EXPECT_FALSE(config.shard_security.tls);

  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"--shard-tls"}, "--shard-tls flags are for --route"},
      {{"--route", "--shards", "a:1", "--shard-tls-ca", "/no/such/ca.pem"},
       "--shard-tls-ca '/no/such/ca.pem'"},
      {{"--route", "--shards", "a:1", "--shard-tls-cert", "/no/such/c.pem"},
       "--shard-tls-cert and --shard-tls-key go together"},
  };
  for (const auto& [args, message] : bad) {
    const Status status = Parse(args, &config);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << message;
    EXPECT_THAT(status.message(), HasSubstr(message));
  }
}

TEST(ServerConfigTest, LogLevelIsInfoUnlessTold) {
  ServerConfig config;
  ASSERT_TRUE(Parse({}, &config).ok());
  EXPECT_EQ(config.log_level, LogLevel::kInfo);
  const std::vector<std::pair<std::string, LogLevel>> levels = {
      {"error", LogLevel::kError},
      {"warning", LogLevel::kWarning},
      {"info", LogLevel::kInfo},
      {"debug", LogLevel::kDebug}};
  for (const auto& [word, level] : levels) {
    ASSERT_TRUE(Parse({"--log-level", word}, &config).ok()) << word;
    EXPECT_EQ(config.log_level, level) << word;
  }
  const Status bad = Parse({"--log-level=verbose"}, &config);
  EXPECT_EQ(bad.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(bad.message(),
            "--log-level 'verbose': must be error, warning, info or debug");
}

TEST(ServerConfigTest, FlagsTakeEqualsOrTheNextWordAndOnlyDatasetRepeats) {
  // The spellings of deploy/k8s/deployment.yaml and deploy/systemd.
  ServerConfig config;
  const Status status =
      Parse({"--listen=0.0.0.0:50051", "--dataset=uniform:1000:1",
             "--dataset=b=uniform:10:2", "--budget=64KiB", "--threads", "2",
             "--redact", "--http-listen=0.0.0.0:9090"},
            &config);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(config.serving.ListenAddress(), "0.0.0.0:50051");
  EXPECT_EQ(config.datasets.size(), 2u);
  EXPECT_EQ(config.engine.tuning.budget_bytes, 64u << 10);
  EXPECT_EQ(config.serving.threads, 2u);
  EXPECT_TRUE(config.access.redact);
  EXPECT_EQ(config.http_port, 9090);
  EXPECT_EQ(Parse({"--listen", "a:1", "--listen=b:2"}, &config).message(),
            "--listen is given twice");
  // Names are matched whole: no prefix of a flag stands for it.
  EXPECT_EQ(Parse({"--thread", "2"}, &config).message(),
            "unknown flag --thread");
}

TEST(ServerConfigTest, RepeatedDatasetFlagsNameDatasetsFirstIsTheDefault) {
  ServerConfig config;
  ASSERT_TRUE(Parse({"--dataset", "terrain=uniform:1000:1", "--dataset",
                     "bedrock=survey.gpkg?layer=pts&z=h", "--dataset",
                     "b.2-x_=ogr:p.csv?oo=X_POSSIBLE_NAMES=x"},
                    &config)
                  .ok());
  EXPECT_EQ(config.datasets,
            (std::vector<DatasetConfig>{
                {"terrain", "uniform:1000:1", true},
                {"bedrock", "survey.gpkg?layer=pts&z=h", true},
                {"b.2-x_", "ogr:p.csv?oo=X_POSSIBLE_NAMES=x", true}}));
  // A bare spec first, then named ones.
  ASSERT_TRUE(
      Parse({"--dataset", "pts.csv", "--dataset", "b=uniform:10"}, &config)
          .ok());
  EXPECT_EQ(config.datasets,
            (std::vector<DatasetConfig>{{"default", "pts.csv", false},
                                        {"b", "uniform:10", true}}));
}

TEST(ServerConfigTest, ASpecWhoseFirstEqualsFollowsNoNameIsBare) {
  // '=' after '?' (OGR options), ':' (generators, ogr:) or '/' (paths).
  for (const char* spec :
       {"survey.gpkg?layer=a", "ogr:p.csv?oo=X_POSSIBLE_NAMES=x", "./a=b.csv",
        "/data/a=b.csv", "uniform:1000:1", ".hidden=x.csv", "-x=y.csv"}) {
    DatasetConfig config;
    ASSERT_TRUE(ParseDatasetFlag(spec, &config).ok()) << spec;
    EXPECT_EQ(config, (DatasetConfig{"default", spec, false})) << spec;
  }
  DatasetConfig config;
  ASSERT_TRUE(ParseDatasetFlag("a=b.csv", &config).ok());
  EXPECT_EQ(config, (DatasetConfig{"a", "b.csv", true}));
  EXPECT_FALSE(IsValidDatasetName(std::string(kMaxDatasetNameLength + 1, 'a')));
  EXPECT_TRUE(IsValidDatasetName(std::string(kMaxDatasetNameLength, 'a')));
}

TEST(ServerConfigTest, BadDatasetListsFailNamingTheProblem) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"--dataset", "a.csv", "--dataset", "b.csv"},
       "only the first --dataset may omit NAME="},
      {{"--dataset", "t=a.csv", "--dataset", "b.csv"},
       "only the first --dataset may omit NAME="},
      {{"--dataset", "t=a.csv", "--dataset", "t=b.csv"},
       "the name 't' is given twice"},
      {{"--dataset", "a.csv", "--dataset", "default=b.csv"},
       "the name 'default' is given twice"},
      {{"--dataset", "t="}, "the dataset spec must not be empty"},
  };
  for (const auto& [args, message] : bad) {
    ServerConfig config;
    const Status status = Parse(args, &config);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << message;
    EXPECT_THAT(status.message(), HasSubstr("--dataset")) << message;
    EXPECT_THAT(status.message(), HasSubstr(message));
  }
}

TEST(ServerConfigTest, HttpFlagsMapToTheConfig) {
  ServerConfig config;
  EXPECT_EQ(config.http_max_body_bytes, size_t{16} << 20);
  ASSERT_TRUE(Parse({"--http-listen", "127.0.0.1:0", "--http-max-body-bytes",
                     "64KiB", "--http-cors-origin", "https://maps.example.org",
                     "--http-cors-origin", "http://localhost:8000"},
                    &config)
                  .ok());
  EXPECT_TRUE(config.http_enabled());
  EXPECT_EQ(config.http_max_body_bytes, 64u << 10);
  EXPECT_EQ(config.http_cors_origins,
            (std::vector<std::string>{"https://maps.example.org",
                                      "http://localhost:8000"}));
}

TEST(ServerConfigTest, HttpLimitAndStatusFlagsMapToTheConfig) {
  ServerConfig config;
  ASSERT_TRUE(Parse({}, &config).ok());
  EXPECT_EQ(config.http_max_grid_cells, uint64_t{1} << 20);
  EXPECT_EQ(config.http_max_connections, 512u);
  EXPECT_EQ(config.http_max_connections_per_address, 64u);
  EXPECT_EQ(config.http_max_waiting_calls, 64u);
  EXPECT_FALSE(config.http_public_status);
  ASSERT_TRUE(Parse({"--http-max-grid-cells", "250000",
                     "--http-max-connections-per-address", "512",
                     "--http-max-waiting-calls", "3", "--http-public-status"},
                    &config)
                  .ok());
  EXPECT_EQ(config.http_max_grid_cells, 250000u);
  EXPECT_EQ(config.http_max_connections_per_address, 512u);
  EXPECT_EQ(config.http_max_waiting_calls, 3u);
  EXPECT_TRUE(config.http_public_status);
}

TEST(ServerConfigTest, MeshCacheMustBeADirectory) {
  const std::string dir = ::testing::TempDir();
  ServerConfig config;
  ASSERT_TRUE(Parse({"--mesh-cache", dir}, &config).ok());
  EXPECT_EQ(config.engine.mesh_cache_dir, dir);
  ServerConfig defaults;
  ASSERT_TRUE(Parse({}, &defaults).ok());
  EXPECT_EQ(defaults.engine.mesh_cache_dir, "");
  EXPECT_EQ(Parse({"--mesh-cache", dir + "/no/such/dir"}, &config).message(),
            "--mesh-cache '" + dir + "/no/such/dir': not a directory");
}

TEST(ServerConfigTest, StateDirMustBeADirectoryForSelfTuning) {
  const std::string dir = ::testing::TempDir();
  ServerConfig config;
  ASSERT_TRUE(Parse({"--state-dir", dir}, &config).ok());
  EXPECT_EQ(config.engine.tuning.state_dir, dir);
  const Status missing = Parse({"--state-dir", dir + "/no/such/dir"}, &config);
  EXPECT_THAT(missing.message(), HasSubstr("--state-dir"));
  EXPECT_THAT(missing.message(), HasSubstr("not a directory"));
  EXPECT_THAT(
      Parse({"--state-dir", dir, "--strategy", "walk"}, &config).message(),
      HasSubstr("only the self-tuning strategy keeps state"));
}

TEST(ServerConfigTest, UnknownFlagsAndStrayArgumentsFail) {
  ServerConfig config;
  EXPECT_THAT(Parse({"--no-such-flag"}, &config).message(),
              HasSubstr("no-such-flag"));
  EXPECT_FALSE(Parse({"stray"}, &config).ok());
  EXPECT_FALSE(Parse({"--threads"}, &config).ok());
}

TEST(ServerConfigTest, ByteFlagsTakeUnitSuffixes) {
  const std::vector<std::pair<std::string, size_t>> cases = {
      {"0", 0}, {"100B", 100}, {"64KiB", 65536}, {"3MiB", 3u << 20}};
  for (const auto& [text, want] : cases) {
    ServerConfig config;
    ASSERT_TRUE(Parse({"--budget", text}, &config).ok()) << text;
    EXPECT_EQ(config.engine.tuning.budget_bytes, want) << text;
  }
  ServerConfig config;
  ASSERT_TRUE(Parse({"--max-message-bytes", "1GiB"}, &config).ok());
  EXPECT_EQ(config.serving.max_message_bytes, size_t{1} << 30);
}

TEST(ServerConfigTest, HttpListenTurnsTheHttpFrontendOn) {
  ServerConfig config;
  ASSERT_TRUE(Parse({"--http-listen", "0.0.0.0:0"}, &config).ok());
  EXPECT_TRUE(config.http_enabled());
  EXPECT_EQ(config.http_host, "0.0.0.0");
  EXPECT_EQ(config.http_port, 0);
  ASSERT_TRUE(Parse({"--http-listen", "[::1]:9090"}, &config).ok());
  EXPECT_EQ(config.http_host, "[::1]");
  EXPECT_EQ(config.http_port, 9090);
}

TEST(ServerConfigTest, ListenAddressSplitsAtTheLastColon) {
  std::string host;
  int port = -1;
  ASSERT_TRUE(ParseListenAddress("[::1]:8080", &host, &port).ok());
  EXPECT_EQ(host, "[::1]");
  EXPECT_EQ(port, 8080);
}

TEST(NoopServerConfigTest, TakesServingFlagsOnly) {
  const std::vector<const char*> good = {"locator-noop-server", "--listen",
                                         "127.0.0.1:0", "--threads", "2"};
  ServingConfig config;
  std::string help;
  ASSERT_TRUE(ParseNoopServerConfig(static_cast<int>(good.size()), good.data(),
                                    &config, &help)
                  .ok());
  EXPECT_EQ(config.listen_port, 0);
  EXPECT_EQ(config.threads, 2u);
  const std::vector<const char*> bad = {"locator-noop-server", "--dataset",
                                        "uniform:10"};
  EXPECT_FALSE(ParseNoopServerConfig(static_cast<int>(bad.size()), bad.data(),
                                     &config, &help)
                   .ok());
}

}  // namespace
}  // namespace locator
