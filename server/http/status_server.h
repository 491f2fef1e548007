// StatusServer: locatord's HTTP side in one place: the Prometheus registry
// with the per-RPC series (fed by a gRPC interceptor) and the per-dataset
// engine series (read at scrape time), each dataset's stats history for
// the status page's charts, and the HTTP server that answers
// StatusEndpoints' paths (GET), the HTTP/JSON API under /v1/ (JsonApi), and
// CORS preflights (CorsPolicy, which also marks every answer to an allowed
// origin). A request body over HttpOptions::max_body_bytes gets 413 with an
// ApiError body.
//
// Owns all of them. It reads the datasets through the LocatorService it is
// given, as GetStats answers them (already redacted, see
// LocatorService::CurrentStats), so a swapped engine is followed.
// Thread-safety: SampleHistory() may be called from any thread; the
// interceptor factory and the HTTP server run on gRPC's and their own
// threads; Listen() once, before port().

#ifndef LOCATOR_SERVER_HTTP_STATUS_SERVER_H_
#define LOCATOR_SERVER_HTTP_STATUS_SERVER_H_

#include <grpcpp/support/server_interceptor.h>
#include <prometheus/registry.h>

#include <map>
#include <memory>
#include <string>

#include "server/http/cors_policy.h"
#include "server/http/http_server.h"
#include "server/http/json_api.h"
#include "server/http/stats_history.h"
#include "server/http/status_endpoints.h"
#include "server/locator_service.h"
#include "server/metrics/engine_collector.h"
#include "server/metrics/rpc_metrics.h"

namespace locator {

class StatusServer {
 public:
  // Sample the history this often (SampleHistory()'s intended period).
  static constexpr double kHistorySeconds = 1.0;

  // Serves `service`'s datasets (not owned; it must outlive this).
  StatusServer(LocatorService* service, HttpOptions options);
  // Waits for the API calls in flight, then stops the HTTP server.
  ~StatusServer();

  // For grpc::ServerBuilder: counts every call into the RPC series. This
  // object must outlive the gRPC server.
  std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>
  NewInterceptorFactory();

  // Starts the HTTP server on host:port (port 0: the OS picks). IOError if
  // the address cannot be bound.
  Status Listen(const std::string& host, int port);
  // The HTTP port bound by Listen().
  int port() const { return http_->port(); }

  // Adds each serving dataset's counters to its history.
  void SampleHistory();

 private:
  // Answers one HTTP request (HttpHandler).
  void Route(HttpRequest request, HttpReply reply);
  // The history of dataset `dataset` ("": the default).
  Status HistoryOf(std::string_view dataset,
                   const StatsHistory** history) const;

  LocatorService* const service_;
  const HttpOptions options_;
  std::shared_ptr<prometheus::Registry> registry_;
  RpcMetrics rpc_metrics_;
  std::shared_ptr<EngineCollector> engine_collector_;
  // One per dataset, by name; the set is fixed at construction.
  std::map<std::string, StatsHistory, std::less<>> histories_;
  StatusEndpoints endpoints_;
  const CorsPolicy cors_;
  JsonApi api_;
  std::unique_ptr<HttpServer> http_;  // last: stopped first
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATUS_SERVER_H_
