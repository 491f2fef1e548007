// locatord: serves point location in one dataset's Delaunay triangulation
// over gRPC (locator.v1.Locator).
//
// The server starts listening (NOT_SERVING) before the dataset is loaded, so
// that orchestration sees the process alive while a large triangulation is
// built; locate calls meanwhile answer UNAVAILABLE. Exit codes: 0 after a
// signal-initiated drain, 1 when the dataset cannot be served or the address
// cannot be bound, 2 for bad flags.

#include <boost/asio/post.hpp>
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>

#include "server/core/dataset.h"
#include "server/core/engine.h"
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

// Loads the dataset and triangulates it, logging progress.
Status BuildEngine(const ServerConfig& config,
                   std::shared_ptr<Engine>* engine) {
  LogLine() << "loading dataset " << config.dataset;
  const auto load_start = std::chrono::steady_clock::now();
  Dataset dataset;
  if (Status status =
          LoadDataset(config.dataset, &dataset, config.dataset_limits);
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
  *engine = std::move(created);
  return Status::OK();
}

// Periodic work acts on whichever engine the service currently publishes.
void StartPeriodicWork(const ServerConfig& config,
                       const LocatorService& service, ServerRunner* runner) {
  if (config.stats_interval_s > 0) {
    runner->RunEvery(config.stats_interval_s, [&service] {
      const EngineStats stats = service.engine()->Stats();
      LogLine() << "stats: queries=" << stats.queries
                << " mean_cost_recent=" << stats.mean_cost_recent
                << " snapshot_version=" << stats.tuning.snapshot_version;
    });
  }
  if (config.retune_interval_s > 0) {
    // On the loop thread, which has nothing else to do between signals.
    runner->RunEvery(config.retune_interval_s,
                     [&service] { service.engine()->Retune(); });
  }
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
      .access = config.access});
  const std::unique_ptr<ServerRunner> runner =
      ServerRunner::StartOrExit(kProgram, config.serving, {&service});
  runner->OnDrain([&service](std::chrono::system_clock::time_point deadline) {
    service.Drain(deadline);
  });

  // The build runs off the loop so that signals are handled meanwhile; its
  // outcome is handed to the loop, which owns every state change. The thread
  // is never joined: the process ends in RunAndExit(), without unwinding
  // this frame, so what the thread refers to here outlives it.
  std::thread([&] {
    std::shared_ptr<Engine> engine;
    const Status status = BuildEngine(config, &engine);
    boost::asio::post(runner->io_context(), [&, status, engine] {
      if (!status.ok()) {
        // Parse errors name the file and line themselves; whole-dataset
        // problems (too few points, all collinear) need the spec said.
        LogLine() << "cannot serve dataset '" << config.dataset
                  << "': " << status.ToString()
                  << (status.code() == Status::Code::kResourceExhausted
                          ? " (see --max-dataset-points)"
                          : "");
        runner->Stop(1);
        return;
      }
      service.Publish(engine);
      runner->SetServing(true);
      LogLine() << "serving " << engine->dataset_info().triangles
                << " triangles";
      StartPeriodicWork(config, service, runner.get());
    });
  }).detach();
  runner->RunAndExit();
}

}  // namespace
}  // namespace locator

int main(int argc, char** argv) { return locator::Main(argc, argv); }
