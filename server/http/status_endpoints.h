// StatusEndpoints: what locatord's HTTP server answers, path by path:
//
//   /metrics      Prometheus text format 0.0.4
//   /api/stats    the engine's statistics: locator.v1.GetStatsResponse as
//                 proto JSON (field names as in the proto, every field
//                 present; 64-bit integers are strings), exactly what
//                 `locator --json stats` prints; 503 with
//                 {"state":"loading"} until an engine serves
//   /api/history  the recent throughput and cost, oldest first:
//                 {"t": [unix s], "qps": [...], "mean_cost": [...]}, null
//                 where an interval located no point
//   /api/edges    what the map draws of the triangulation, each a list of
//                 [x0, y0, x1, y1]: {"segments": a sample of its edges,
//                 "boundary": the domain's boundary and holes,
//                 "breaklines": its breaklines}, each at most 3000 long
//                 (Engine::kEdgeSampleSize, Engine::kOutlineSize; evenly
//                 thinned beyond), the last two empty without constraints;
//                 503 while loading
//   /            the status page (index.html); other embedded page files
//                by name, e.g. /app.js
//   otherwise    404
//
// Owns nothing but the functions and pointers it reads from; the statistics
// are fetched per request, so a swapped engine shows at once. They come
// already redacted (--redact): this class never sees an Engine.
// Thread-safety: Handle() may be called from any thread, as far as the
// sources allow it (they are all thread-safe in locatord).

#ifndef LOCATOR_SERVER_HTTP_STATUS_ENDPOINTS_H_
#define LOCATOR_SERVER_HTTP_STATUS_ENDPOINTS_H_

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "common/geometry.h"
#include "server/http/http_server.h"
#include "server/http/stats_history.h"
#include "server/metrics/engine_collector.h"

namespace locator {

// The lines /api/edges serves, as endpoint pairs.
struct MapEdges {
  // A sample of the triangulation's edges (Engine::EdgeSample).
  std::vector<std::array<Point2, 2>> segments;
  // Domain boundary and holes, and breaklines (Engine::domain_outline).
  std::vector<std::array<Point2, 2>> boundary;
  std::vector<std::array<Point2, 2>> breaklines;
};

// Fills its argument with the serving triangulation's map edges; false
// while no engine serves.
using EdgeSource = std::function<bool(MapEdges*)>;

struct StatusSources {
  // The serving engine's statistics, as GetStats answers them.
  StatsSource stats;
  EdgeSource edges;
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
