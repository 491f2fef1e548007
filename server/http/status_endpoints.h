// StatusEndpoints: what locatord's HTTP server answers, path by path:
//
//   /metrics     Prometheus text format 0.0.4
//   /api/stats   the engine's statistics and recent history (stats_json.h);
//                503 with {"state": "loading"} until an engine serves
//   /api/edges   a sample of the triangulation's edges; 503 while loading
//   /            the status page (index.html); other embedded page files
//                by name, e.g. /app.js
//   otherwise    404
//
// Owns nothing but the functions and pointers it reads from; the engine is
// fetched per request, so a swapped engine shows at once.
// Thread-safety: Handle() may be called from any thread, as far as the
// sources allow it (they are all thread-safe in locatord).

#ifndef LOCATOR_SERVER_HTTP_STATUS_ENDPOINTS_H_
#define LOCATOR_SERVER_HTTP_STATUS_ENDPOINTS_H_

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "server/core/engine.h"
#include "server/http/http_server.h"
#include "server/http/stats_history.h"

namespace locator {

struct StatusSources {
  // The engine new calls use, or null while loading.
  std::function<std::shared_ptr<Engine>()> current_engine;
  // Must outlive the endpoints.
  const StatsHistory* history = nullptr;
  // The /metrics body.
  std::function<std::string()> metrics_text;
};

class StatusEndpoints {
 public:
  explicit StatusEndpoints(StatusSources sources);

  // The response for a GET of `path`.
  HttpResponse Handle(std::string_view path) const;

 private:
  // The response for an engine-backed API path, or 404 for another path.
  HttpResponse Api(std::string_view path) const;
  // The embedded page file at `path`, or 404.
  static HttpResponse PageFile(std::string_view path);

  const StatusSources sources_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATUS_ENDPOINTS_H_
