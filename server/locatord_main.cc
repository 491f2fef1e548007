// locatord: serves point location in one dataset's Delaunay triangulation
// over gRPC (locator.v1.Locator).
//
// The server starts listening (NOT_SERVING) before the dataset is loaded, so
// that orchestration sees the process alive while a large triangulation is
// built; locate calls meanwhile answer UNAVAILABLE. Exit codes: 0 after a
// signal-initiated drain, 1 when the dataset cannot be served or the address
// cannot be bound, 2 for bad flags.

#include <array>
#include <boost/asio/post.hpp>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "server/core/dataset.h"
#include "server/core/engine.h"
#include "server/dataset_source.h"
#include "server/http/status_server.h"
#include "server/locator_service.h"
#include "server/server_config.h"
#include "server/server_runner.h"

namespace locator {
namespace {

constexpr char kProgram[] = "locatord";

// One stderr line, written whole when the statement ends.
class LogLine {
 public:
  LogLine() { line_ << kProgram << ' '; }
  ~LogLine() { std::cerr << line_.str() << std::endl; }
  template <typename T>
  LogLine& operator<<(const T& value) {
    line_ << value;
    return *this;
  }

 private:
  std::ostringstream line_;
};

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

// Writes `engine`'s learned tuning to the state dir if it changed since the
// last save. A failure is logged; serving goes on.
void SaveTuningStateOrWarn(Engine& engine, std::string_view when) {
  const Status status = engine.SaveTuningState();
  if (!status.ok()) {
    LogLine() << "warning: cannot save the tuning state " << when << ": "
              << status.ToString();
  }
}

// Says where a new engine's tuning came from, and why a state file in the
// state dir was ignored.
void LogTuningState(const Engine& engine) {
  const PersistenceSummary p = engine.Stats().tuning.persistence;
  if (p.state_path.empty()) return;
  if (p.restored_from_state) {
    LogLine() << "restored the tuning state from " << p.state_path;
  } else if (!p.load_error.empty()) {
    LogLine() << "warning: ignoring the tuning state " << p.state_path << ": "
              << p.load_error;
  } else {
    LogLine() << "no tuning state at " << p.state_path << " yet";
  }
}

// Loads the dataset and triangulates it, logging progress.
Status LoadAndTriangulate(const ServerConfig& config,
                          const std::string& dataset_spec,
                          std::shared_ptr<Engine>* engine) {
  LogLine() << "loading dataset " << dataset_spec;
  const auto load_start = std::chrono::steady_clock::now();
  Dataset dataset;
  if (Status status =
          LoadServedDataset(dataset_spec, config.dataset_limits, &dataset);
      !status.ok()) {
    return status;
  }
  LogLine() << "loaded " << dataset.points.size() << " points in "
            << SecondsSince(load_start) << " s; triangulating";
  std::unique_ptr<Engine> created;
  if (Status status =
          Engine::Create(std::move(dataset), config.engine, &created);
      !status.ok()) {
    return status;
  }
  const DatasetInfo& info = created->dataset_info();
  LogLine() << "built " << info.triangles << " triangles over " << info.vertices
            << " vertices (" << info.duplicates_merged
            << " duplicates merged) in " << info.build_seconds << " s";
  LogTuningState(*created);
  *engine = std::move(created);
  return Status::OK();
}

// Builds the engine for `spec` ("": --dataset) at start and on reloads.
// Before a reload it saves the serving engine's tuning, so that reloading
// the same points continues from it.
Status BuildEngine(const ServerConfig& config, const std::string& spec,
                   Engine* serving, std::shared_ptr<Engine>* engine) {
  if (serving != nullptr) SaveTuningStateOrWarn(*serving, "before the reload");
  const Status status =
      LoadAndTriangulate(config, spec.empty() ? config.dataset : spec, engine);
  if (!status.ok() && serving != nullptr) {
    LogLine() << "reload failed, still serving the previous dataset: "
              << status.ToString();
  }
  return status;
}

// SIGHUP reloads the configured dataset, like a Reload RPC without one.
void ReloadOnHangup(const ServerConfig& config, LocatorService& service) {
  LogLine() << "SIGHUP: reloading " << config.dataset;
  const Status started = service.StartReload(
      "", [](const Status& status, std::shared_ptr<Engine> engine,
             uint64_t generation) {
        if (!status.ok()) return;  // BuildEngine said why
        LogLine() << "reloaded: serving " << engine->dataset_info().triangles
                  << " triangles as generation " << generation;
      });
  if (!started.ok()) LogLine() << "SIGHUP ignored: " << started.message();
}

// Periodic work acts on whichever engine the service currently publishes.
void StartPeriodicWork(const ServerConfig& config,
                       const LocatorService& service, StatusServer* status,
                       ServerRunner* runner) {
  if (status != nullptr) {
    // The first sample is the baseline the first interval is measured from.
    status->SampleHistory();
    runner->RunEvery(StatusServer::kHistorySeconds,
                     [status] { status->SampleHistory(); });
  }
  if (config.stats_interval_s > 0) {
    runner->RunEvery(config.stats_interval_s, [&service] {
      v1::GetStatsResponse stats;
      if (!service.CurrentStats(&stats)) return;
      LogLine() << "stats: queries=" << stats.queries_served()
                << " mean_cost_recent=" << stats.mean_cost_recent()
                << " snapshot_version=" << stats.tuning().snapshot_version();
    });
  }
  if (config.retune_interval_s > 0) {
    // On the loop thread, which has nothing else to do between signals.
    runner->RunEvery(config.retune_interval_s,
                     [&service] { service.engine()->Retune(); });
  }
}

// On the loop thread, once the first engine is built (and published) or
// its build failed.
void ServeOrExit(const Status& built, const Engine* engine,
                 const ServerConfig& config, const LocatorService& service,
                 StatusServer* status_server, ServerRunner* runner) {
  if (!built.ok()) {
    // Parse errors name the file and line themselves; whole-dataset
    // problems (too few points, all collinear) need the spec said.
    LogLine() << "cannot serve dataset '" << config.dataset
              << "': " << built.ToString()
              << (built.code() == Status::Code::kResourceExhausted
                      ? " (see --max-dataset-points)"
                      : "");
    runner->Stop(1);
    return;
  }
  runner->SetServing(true);
  LogLine() << "serving " << engine->dataset_info().triangles << " triangles";
  StartPeriodicWork(config, service, status_server, runner);
}

// Ends the process once ServerRunner::Run() has returned `exit_code`: the
// log streams are flushed, and nothing still alive is torn down (see
// ServerRunner::Run() for why).
[[noreturn]] void ExitWithoutTeardown(int exit_code) {
  std::cout.flush();
  std::cerr.flush();
  std::_Exit(exit_code);
}

int Main(int argc, char** argv) {
  ServerConfig config;
  std::string help;
  const Status parsed = ParseServerConfig(argc, argv, &config, &help);
  if (std::optional<int> exit_code = ExitCodeForFlags(kProgram, parsed, help)) {
    return *exit_code;
  }

  LocatorService service(LocatorServiceOptions{
      .batch_threads = config.serving.threads,
      .max_batch_points = config.serving.max_batch_points,
      .default_deadline = config.serving.transport.default_deadline,
      .access = config.access,
      .reload_policy = ReloadPolicy(config.dataset, config.reload_dir),
      .build_engine = [&config](const std::string& spec, Engine* serving,
                                std::shared_ptr<Engine>* engine) {
        return BuildEngine(config, spec, serving, engine);
      }});
  // With --http-listen, every gRPC call is counted for /metrics.
  std::unique_ptr<StatusServer> status_server;
  std::vector<
      std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>>
      interceptors;
  if (config.http_enabled()) {
    // It gets the statistics as GetStats answers them (redacted with
    // --redact), never the engine's own.
    status_server = std::make_unique<StatusServer>(
        [&service](v1::GetStatsResponse* stats) {
          return service.CurrentStats(stats);
        },
        [&service](MapEdges* edges) {
          const std::shared_ptr<Engine> engine = service.engine();
          if (engine == nullptr) return false;
          edges->segments = engine->EdgeSample();
          edges->boundary = engine->domain_outline().boundary;
          edges->breaklines = engine->domain_outline().breaklines;
          return true;
        });
    interceptors.push_back(status_server->NewInterceptorFactory());
  }
  std::unique_ptr<ServerRunner> runner;
  if (Status started = ServerRunner::Start(kProgram, config.serving, {&service},
                                           std::move(interceptors), &runner);
      !started.ok()) {
    std::cerr << kProgram << ": " << started.message() << std::endl;
    return 1;
  }
  if (status_server != nullptr) {
    if (Status listening =
            status_server->Listen(config.http_host, config.http_port);
        !listening.ok()) {
      std::cerr << kProgram << ": " << listening.message() << std::endl;
      runner->Stop(1);
      ExitWithoutTeardown(runner->Run());
    }
    std::cout << kProgram << " http listening on " << config.http_host << ":"
              << status_server->port() << std::endl;
  }
  runner->OnDrain([&service](std::chrono::system_clock::time_point deadline) {
    service.Drain(deadline);
  });
  runner->OnHangup([&] { ReloadOnHangup(config, service); });
  runner->BeforeExit([&service] {
    if (std::shared_ptr<Engine> engine = service.engine()) {
      SaveTuningStateOrWarn(*engine, "at exit");
    }
  });

  // The first build is a reload from nothing, which nothing can refuse. It
  // runs off the loop so that signals are handled meanwhile, and hands its
  // outcome to the loop, which owns every state change of the process. What
  // the callbacks refer to here outlives them: the process ends below
  // without unwinding this frame.
  const Status first_build = service.StartReload(
      "", [&](const Status& status, std::shared_ptr<Engine> engine,
              uint64_t /*generation*/) {
        boost::asio::post(runner->io_context(), [&, status, engine] {
          ServeOrExit(status, engine.get(), config, service,
                      status_server.get(), runner.get());
        });
      });
  if (!first_build.ok()) {
    LogLine() << "cannot load dataset '" << config.dataset
              << "': " << first_build.ToString();
    runner->Stop(1);
  }
  ExitWithoutTeardown(runner->Run());
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) { return locator::Main(argc, argv); }
