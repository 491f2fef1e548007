// locatord: serves point location in the triangulations of one or more
// named datasets over gRPC (locator.v1.Locator) and, with --http-listen,
// HTTP/JSON.
//
// The server starts listening (NOT_SERVING) before any dataset is loaded,
// so that orchestration sees the process alive while large triangulations
// are built; the datasets are built one after another, in flag order, and
// calls to one still loading answer UNAVAILABLE. Health reports SERVING
// once every dataset serves. Exit codes: 0 after a signal-initiated drain,
// 1 when a dataset cannot be served or an address cannot be bound, 2 for bad
// flags.

#include <boost/asio/post.hpp>
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/flags/flag_set.h"
#include "common/grpc_lifetime.h"
#include "locator/engine.h"
#include "server/app/locator_app.h"
#include "server/config/server_config.h"
#include "server/config/server_log.h"
#include "server/datasets/dataset_builder.h"
#include "server/datasets/dataset_registry.h"
#include "server/grpc/locator_service.h"
#include "server/http/http_frontend.h"
#include "server/main/server_runner.h"
#include "server/metrics/rpc_metrics.h"
#include "server/route/router_main.h"

namespace locator {
namespace {

constexpr char kProgram[] = "locatord";

// SIGHUP reloads every dataset that serves from its configured spec, each
// on its own, like a Reload RPC naming it; one still loading its first
// engine is left to finish.
void ReloadOnHangup(LocatorApp& app, const DatasetBuilder& builder) {
  for (const std::unique_ptr<DatasetSlot>& slot : app.datasets().slots()) {
    const std::string_view tag = builder.Tag(*slot);
    if (slot->serving().engine == nullptr) {
      LogLine(LogLevel::kWarning, tag) << "SIGHUP: still loading, not reloaded";
      continue;
    }
    LogLine(LogLevel::kInfo, tag) << "SIGHUP: reloading " << slot->spec();
    const Status started = slot->StartReload(
        "", [tag](const Status& status, std::shared_ptr<Engine> engine,
                  uint64_t generation) {
          if (!status.ok()) return;  // DatasetBuilder said why
          LogLine(LogLevel::kInfo, tag)
              << "reloaded: serving " << engine->dataset_info().triangles
              << " triangles as generation " << generation;
        });
    if (!started.ok())
      LogLine(LogLevel::kWarning, tag)
          << "SIGHUP ignored: " << started.message();
  }
}

// Periodic work acts on whichever engines the datasets serve at the time.
void StartPeriodicWork(const ServerConfig& config, LocatorApp& app,
                       const DatasetBuilder& builder, HttpFrontend* status,
                       ServerRunner* runner) {
  if (status != nullptr) {
    // The first sample is the baseline the first interval is measured from.
    status->SampleHistory();
    runner->RunEvery(HttpFrontend::kHistorySeconds,
                     [status] { status->SampleHistory(); });
  }
  if (config.stats_interval_s > 0) {
    runner->RunEvery(config.stats_interval_s, [&app, &builder] {
      for (const std::unique_ptr<DatasetSlot>& slot : app.datasets().slots()) {
        StatusOr<v1::GetStatsResponse> stats = app.CurrentStats(slot->name());
        if (!stats.ok()) continue;
        LogLine(LogLevel::kInfo, builder.Tag(*slot))
            << "stats: queries=" << stats->queries_served()
            << " mean_cost_recent=" << stats->mean_cost_recent()
            << " snapshot_version=" << stats->tuning().snapshot_version();
      }
    });
  }
  if (config.retune_interval_s > 0) {
    // On the loop thread, which has nothing else to do between signals.
    runner->RunEvery(config.retune_interval_s, [&app, &builder] {
      for (const std::unique_ptr<DatasetSlot>& slot : app.datasets().slots()) {
        if (std::shared_ptr<Engine> engine = slot->serving().engine) {
          engine->Retune();
          LogLine(LogLevel::kDebug, builder.Tag(*slot))
              << "re-tuned (--retune-interval-s)";
        }
      }
    });
  }
}

// Builds the datasets' first engines one after another, in flag order, so
// that the point budget is taken in that order; once all serve, the server
// reports SERVING. A dataset that cannot be built stops the server.
class StartupBuilds {
 public:
  StartupBuilds(const ServerConfig& config, LocatorApp& app,
                const DatasetBuilder& builder, HttpFrontend* http_frontend,
                ServerRunner* runner)
      : config_(config),
        app_(app),
        builder_(builder),
        http_frontend_(http_frontend),
        runner_(runner) {}

  // Starts building dataset `index` (the first: 0). The build runs off the
  // loop, so that signals are handled meanwhile, and hands its outcome to
  // the loop, which owns every state change of the process.
  void Start(size_t index) {
    DatasetSlot& slot = *app_.datasets().slots()[index];
    // A first build is a reload from nothing, which nothing can refuse.
    const Status started = slot.StartReload(
        "", [this, index](const Status& status, std::shared_ptr<Engine> engine,
                          uint64_t /*generation*/) {
          boost::asio::post(runner_->io_context(),
                            [this, index, status, engine] {
                              Built(index, status, engine.get());
                            });
        });
    if (!started.ok()) Fail(slot, started);
  }

 private:
  // On the loop thread, once dataset `index`'s first build has ended.
  // `engine` is the one built (null when the build failed).
  void Built(size_t index, const Status& status, const Engine* engine) {
    const DatasetSlot& slot = *app_.datasets().slots()[index];
    if (!status.ok()) {
      Fail(slot, status);
      return;
    }
    LogLine(LogLevel::kInfo, builder_.Tag(slot))
        << "serving " << engine->dataset_info().triangles << " triangles";
    if (index + 1 < app_.datasets().slots().size()) {
      Start(index + 1);
      return;
    }
    runner_->SetServing(true);
    if (index > 0) {
      LogLine(LogLevel::kInfo) << "serving all " << index + 1 << " datasets";
    }
    StartPeriodicWork(config_, app_, builder_, http_frontend_, runner_);
  }

  void Fail(const DatasetSlot& slot, const Status& status) {
    // Parse errors name the file and line themselves; whole-dataset
    // problems (too few points, all collinear) need the spec said.
    LogLine(LogLevel::kError)
        << "cannot serve dataset "
        << (slot.named() ? slot.name() + "=" : std::string()) << "'"
        << slot.spec() << "': " << status.ToString();
    runner_->Stop(1);
  }

  const ServerConfig& config_;
  LocatorApp& app_;
  const DatasetBuilder& builder_;
  HttpFrontend* const http_frontend_;
  ServerRunner* const runner_;
};

int Main(int argc, char** argv) {
  ServerConfig config;
  std::string help;
  const Status parsed = ParseServerConfig(argc, argv, &config, &help);
  if (std::optional<int> exit_code = ExitCodeForFlags(kProgram, parsed, help)) {
    return *exit_code;
  }
  SetLogLevel(config.log_level);
  if (config.route) RunRouter(kProgram, config);

  DatasetBuilder builder(config);
  LocatorApp app(LocatorAppOptions{
      .batch_threads = config.serving.threads,
      .max_batch_points = config.serving.max_batch_points,
      .max_profile_crossings = config.serving.max_profile_crossings,
      .max_profile_samples = config.serving.max_profile_samples,
      .max_grid_cells = config.serving.max_grid_cells,
      .default_deadline = config.serving.transport.default_deadline,
      .access = config.access,
      .datasets = config.datasets,
      .reload_dir = config.reload_dir,
      .build_engine = [&builder](const DatasetSlot& slot,
                                 const std::string& spec, Engine* serving,
                                 BuiltDataset* built) {
        return builder.Build(slot, spec, serving, built);
      }});
  LocatorService service(&app);
  // With --http-listen, every gRPC call is counted for /metrics.
  std::unique_ptr<HttpFrontend> http_frontend;
  std::optional<RpcMetrics> rpc_metrics;
  std::vector<
      std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>>
      interceptors;
  if (config.http_enabled()) {
    auto registry = std::make_shared<prometheus::Registry>();
    rpc_metrics.emplace(
        registry.get(),
        ServerRunner::MethodsServed({v1::Locator::service_full_name()}));
    interceptors.push_back(rpc_metrics->NewInterceptorFactory());
    http_frontend = std::make_unique<HttpFrontend>(
        &app,
        HttpOptions{.limits = {.max_body_bytes = config.http_max_body_bytes,
                               .max_connections = config.http_max_connections,
                               .max_connections_per_address =
                                   config.http_max_connections_per_address},
                    .cors_origins = config.http_cors_origins,
                    .api = {.max_grid_cells = config.http_max_grid_cells,
                            .max_waiting_calls = config.http_max_waiting_calls},
                    .public_status = config.http_public_status},
        std::move(registry));
  }
  std::unique_ptr<ServerRunner> runner;
  if (Status started = ServerRunner::Start(kProgram, config.serving, {&service},
                                           std::move(interceptors), &runner);
      !started.ok()) {
    std::cerr << kProgram << ": " << started.message() << std::endl;
    return 1;
  }
  if (http_frontend != nullptr) {
    if (Status listening =
            http_frontend->Listen(config.http_host, config.http_port);
        !listening.ok()) {
      std::cerr << kProgram << ": " << listening.message() << std::endl;
      runner->Stop(1);
      ExitWithoutTeardown(runner->Run());
    }
    std::cout << kProgram << " http listening on " << config.http_host << ":"
              << http_frontend->port() << std::endl;
  }
  runner->OnDrain([&app](std::chrono::system_clock::time_point deadline) {
    app.Drain(deadline);
  });
  runner->OnHangup([&] { ReloadOnHangup(app, builder); });
  runner->BeforeExit([&app, &builder] {
    for (const std::unique_ptr<DatasetSlot>& slot : app.datasets().slots()) {
      if (std::shared_ptr<Engine> engine = slot->serving().engine) {
        DatasetBuilder::SaveTuningStateOrWarn(*engine, builder.Tag(*slot),
                                              "at exit");
      }
    }
  });

  // What the callbacks refer to here outlives them: the process ends below
  // without unwinding this frame.
  StartupBuilds startup(config, app, builder, http_frontend.get(),
                        runner.get());
  startup.Start(0);
  ExitWithoutTeardown(runner->Run());
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) {
  // Outlives every gRPC object Main() makes (see grpc_lifetime.h).
  const locator::GrpcLifetime grpc;
  return locator::Main(argc, argv);
}
