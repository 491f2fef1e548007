// StatusServer: locatord's HTTP side in one place: the Prometheus registry
// with the per-RPC series (fed by a gRPC interceptor) and the per-dataset
// engine series (read at scrape time), each dataset's stats history for
// the status page's charts, and the HTTP server that answers
// StatusEndpoints' paths (GET), the HTTP/JSON API under /v1/ (JsonApi), and
// CORS preflights (CorsPolicy, which also marks every answer to an allowed
// origin). What the HTTP server could not read as a request gets an ApiError
// and the connection closes: a body over the limit 413, a header over the
// limit 431, a malformed request 400, a connection over the limits 503 with
// Retry-After. A POST to the API must say Content-Type: application/json
// (415 otherwise): a page of another origin can send a "simple" text/plain
// POST without asking the browser first (no CORS preflight), and it would
// run. With tokens, /api/stats and /api/edges want the data token as
// GetStats does, unless HttpOptions::public_status.
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
#include <vector>

#include "server/grpc/locator_service.h"
#include "server/http/cors_policy.h"
#include "server/http/http_server.h"
#include "server/http/json/json_api.h"
#include "server/http/status/stats_history.h"
#include "server/http/status/status_endpoints.h"
#include "server/metrics/engine_collector.h"
#include "server/metrics/rpc_metrics.h"

namespace locator {

struct HttpOptions {
  // --http-max-body-bytes, --http-max-connections-per-address.
  HttpLimits limits;
  // --http-cors-origin: origins allowed to call the server from web pages
  // (CORS; see CorsPolicy); empty: CORS off.
  std::vector<std::string> cors_origins;
  // --http-max-grid-cells, --http-max-waiting-calls.
  JsonApiOptions api;
  // --http-public-status: /api/stats and /api/edges answer without a token.
  bool public_status = false;
};

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
  // The answer to a request the HTTP server could not read (see above).
  HttpResponse ProblemAnswer(const HttpRequest& request) const;
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
