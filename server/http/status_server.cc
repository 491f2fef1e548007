#include "server/http/status_server.h"

#include <chrono>
#include <utility>

#include "server/metrics/metrics_text.h"

namespace locator {

StatusServer::StatusServer(
    std::function<std::shared_ptr<Engine>()> current_engine)
    : current_engine_(std::move(current_engine)),
      registry_(std::make_shared<prometheus::Registry>()),
      rpc_metrics_(registry_.get()),
      engine_collector_(std::make_shared<EngineCollector>(current_engine_)),
      endpoints_(
          StatusSources{.current_engine = current_engine_,
                        .history = &history_,
                        .metrics_text = [this] {
                          return MetricsText({registry_, engine_collector_});
                        }}) {}

std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>
StatusServer::NewInterceptorFactory() {
  return rpc_metrics_.NewInterceptorFactory();
}

Status StatusServer::Listen(const std::string& host, int port) {
  return HttpServer::Start(
      host, port,
      [this](std::string_view path) { return endpoints_.Handle(path); },
      &http_);
}

void StatusServer::SampleHistory() {
  const std::shared_ptr<Engine> engine = current_engine_();
  if (engine == nullptr) return;
  const EngineStats stats = engine->Stats();
  history_.Record(reinterpret_cast<uintptr_t>(engine.get()), stats.queries,
                  stats.total_cost, std::chrono::system_clock::now());
}

}  // namespace locator
