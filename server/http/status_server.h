// StatusServer: locatord's observability in one place: the Prometheus
// registry with the per-RPC series (fed by a gRPC interceptor) and the
// engine series (read at scrape time), the stats history the status page
// charts, and the HTTP server that answers StatusEndpoints' paths.
//
// Owns all of them. It never sees an Engine: the statistics (already
// redacted, see StatsSource) and the edge sample are fetched through the
// functions it is given, per use, so a swapped engine is followed.
// Thread-safety: SampleHistory() may be called from any thread; the
// interceptor factory and the HTTP server run on gRPC's and their own
// threads; Listen() once, before port().

#ifndef LOCATOR_SERVER_HTTP_STATUS_SERVER_H_
#define LOCATOR_SERVER_HTTP_STATUS_SERVER_H_

#include <grpcpp/support/server_interceptor.h>
#include <prometheus/registry.h>

#include <memory>
#include <string>

#include "server/http/http_server.h"
#include "server/http/stats_history.h"
#include "server/http/status_endpoints.h"
#include "server/metrics/engine_collector.h"
#include "server/metrics/rpc_metrics.h"

namespace locator {

class StatusServer {
 public:
  // Sample the history this often (SampleHistory()'s intended period).
  static constexpr double kHistorySeconds = 1.0;

  StatusServer(StatsSource stats, EdgeSource edges);

  // For grpc::ServerBuilder: counts every call into the RPC series. This
  // object must outlive the gRPC server.
  std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>
  NewInterceptorFactory();

  // Starts the HTTP server on host:port (port 0: the OS picks). IOError if
  // the address cannot be bound.
  Status Listen(const std::string& host, int port);
  // The HTTP port bound by Listen().
  int port() const { return http_->port(); }

  // Adds the serving engine's counters to the history (nothing while no
  // engine serves).
  void SampleHistory();

 private:
  const StatsSource stats_;
  std::shared_ptr<prometheus::Registry> registry_;
  RpcMetrics rpc_metrics_;
  std::shared_ptr<EngineCollector> engine_collector_;
  StatsHistory history_;
  StatusEndpoints endpoints_;
  std::unique_ptr<HttpServer> http_;  // last: stopped first
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATUS_SERVER_H_
