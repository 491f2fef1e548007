#include "server/http/status_server.h"

#include <chrono>
#include <utility>

#include "server/metrics/metrics_text.h"

namespace locator {

StatusServer::StatusServer(StatsSource stats, EdgeSource edges)
    : stats_(std::move(stats)),
      registry_(std::make_shared<prometheus::Registry>()),
      rpc_metrics_(registry_.get()),
      engine_collector_(std::make_shared<EngineCollector>(stats_)),
      endpoints_(
          StatusSources{.stats = stats_,
                        .edges = std::move(edges),
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
  v1::GetStatsResponse stats;
  if (!stats_(&stats)) return;
  history_.Record(stats.generation(), stats.queries_served(),
                  stats.total_cost(), std::chrono::system_clock::now());
}

}  // namespace locator
