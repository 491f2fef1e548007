// HttpFrontend: locatord's HTTP side in one place: /metrics (the
// Prometheus registry it is given, holding the per-RPC series, and the
// per-dataset engine series read at scrape time), each dataset's stats
// history for
// the status page's charts, and the HTTP server that answers
// StatusEndpoints' paths (GET), the HTTP/JSON API under /v1/ (JsonApi), and
// CORS preflights (CorsPolicy, which also marks every answer to an allowed
// origin), and the elevation APIs in JsonApi's lanes: Open Topo Data under
// /opentopodata/ (OpenTopoDataApi) and OGC API - EDR under /edr/ (EdrApi). What
// the HTTP server could not read as a request gets an ApiError and the
// connection closes: a body over the limit 413, a header over the limit 431, a
// malformed request 400, a connection over the limits 503 with Retry-After. A
// POST to the API must say Content-Type: application/json (415 otherwise): a
// page of another origin can send a "simple" text/plain POST without asking the
// browser first (no CORS preflight), and it would run. With tokens, /api/stats
// and /api/edges want the data token as GetStats does, unless
// HttpOptions::public_status.
//
// Owns all of them but the registry, which it shares. It reads the datasets
// through the application it is given, as GetStats answers them (already
// redacted, see LocatorApp::CurrentStats), so a swapped engine is followed.
// Thread-safety: SampleHistory() may be called from any thread; the HTTP
// server runs on its own threads; Listen() once, before port().

#ifndef LOCATOR_SERVER_HTTP_STATUS_SERVER_H_
#define LOCATOR_SERVER_HTTP_STATUS_SERVER_H_

#include <prometheus/registry.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "server/app/locator_app.h"
#include "server/http/cors_policy.h"
#include "server/http/edr/edr_api.h"
#include "server/http/http_server.h"
#include "server/http/json/json_api.h"
#include "server/http/opentopodata/open_topo_data_api.h"
#include "server/http/status/stats_history.h"
#include "server/http/status/status_endpoints.h"
#include "server/metrics/engine_collector.h"

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

// What every HTTP front of a server (locatord's, the router's) does with a
// request first: answers a CORS preflight, makes *reply add the CORS
// headers `cors` gives the request's origin (which must outlive the
// reply), and answers a request the server could not read (too large,
// malformed, over `limits`) and a POST to the API (/v1/) that does not say
// Content-Type: application/json (415: see above). True when the request
// is answered.
bool ReceiveRequest(const CorsPolicy& cors, const HttpLimits& limits,
                    const HttpRequest& request, HttpReply* reply);

class HttpFrontend {
 public:
  // Sample the history this often (SampleHistory()'s intended period).
  static constexpr double kHistorySeconds = 1.0;

  // Serves `app`'s datasets (not owned; it must outlive this), with
  // `registry`'s series on /metrics besides the engines'.
  HttpFrontend(LocatorApp* app, HttpOptions options,
               std::shared_ptr<prometheus::Registry> registry);
  // Waits for the API calls in flight, then stops the HTTP server.
  ~HttpFrontend();

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

  LocatorApp* const app_;
  const HttpOptions options_;
  std::shared_ptr<prometheus::Registry> registry_;
  std::shared_ptr<EngineCollector> engine_collector_;
  // One per dataset, by name; the set is fixed at construction.
  std::map<std::string, StatsHistory, std::less<>> histories_;
  StatusEndpoints endpoints_;
  const CorsPolicy cors_;
  JsonApi api_;
  OpenTopoDataApi open_topo_data_;  // these two run in api_'s lanes
  EdrApi edr_;
  std::unique_ptr<HttpServer> http_;  // last: stopped first
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATUS_SERVER_H_
