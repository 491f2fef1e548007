// StatusEndpoints: what locatord's HTTP server answers to GET, path by path
// (the HTTP/JSON API under /v1/ is JsonApi's):
//
//   /metrics      Prometheus text format 0.0.4
//   /api/stats    a dataset's statistics: locator.v1.GetStatsResponse as
//                 proto JSON (field names as in the proto, every field
//                 present; 64-bit integers are strings), exactly what
//                 `locator --json stats` prints; 503 with
//                 {"state":"loading"} until its engine serves
//   /api/history  its recent throughput and cost, oldest first:
//                 {"t": [unix s], "qps": [...], "mean_cost": [...]}, null
//                 where an interval located no point
//   /api/edges    what the map draws of its triangulation, each a list of
//                 [x0, y0, x1, y1]: {"segments": a sample of its edges,
//                 "boundary": the domain's boundary and holes,
//                 "breaklines": its breaklines}, each at most 3000 long
//                 (kEdgeSampleSize, kOutlineSize; evenly
//                 thinned beyond), the last two empty without constraints;
//                 503 while loading
//   /            the status page (index.html); other embedded page files
//                by name, e.g. /app.js
//   /web/        the web map (client/web/: index.html, and its files
//                by name)
//   otherwise    404
//
// The /api/ paths take ?dataset=NAME (default: the default dataset); an
// unknown name is 404 with an ApiError body. /api/stats and /api/edges show
// what GetStats shows (the source, real coordinates), so they are admitted
// as GetStats is, by StatusSources::authorize (401 / 403 with an ApiError
// body when it refuses); the other paths are public.
//
// Owns nothing but the functions it reads from; the statistics are fetched
// per request, so a swapped engine shows at once. They come already
// redacted (--redact): this class never sees an Engine.
// Thread-safety: Handle() may be called from any thread, as far as the
// sources allow it (they are all thread-safe in locatord).

#ifndef LOCATOR_SERVER_HTTP_STATUS_ENDPOINTS_H_
#define LOCATOR_SERVER_HTTP_STATUS_ENDPOINTS_H_

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"
#include "server/http/http_server.h"
#include "server/http/status/stats_history.h"
#include "server/metrics/engine_collector.h"

namespace locator {

// Fills its argument with the statistics of dataset `dataset` ("": the
// default) as GetStats answers them. NotFound for an unknown dataset,
// Unavailable while it is loading.
using StatsSource =
    std::function<Status(std::string_view dataset, v1::GetStatsResponse*)>;
// The lines /api/edges serves, as endpoint pairs.
struct MapEdges {
  // A sample of the triangulation's edges (Engine::EdgeSample).
  std::vector<std::array<Point2, 2>> segments;
  // Domain boundary and holes, and breaklines (Engine::domain_outline).
  std::vector<std::array<Point2, 2>> boundary;
  std::vector<std::array<Point2, 2>> breaklines;
};

// The same for the lines the map draws of the dataset's triangulation.
using EdgeSource =
    std::function<Status(std::string_view dataset, MapEdges* edges)>;
// The history of dataset `dataset` ("": the default); NotFound for an
// unknown one. The history must outlive the endpoints.
using HistorySource = std::function<Status(std::string_view dataset,
                                           const StatsHistory** history)>;

// OK if a request presenting `authorization` (its Authorization header;
// nullopt without one) may read a dataset's statistics and edges, otherwise
// the refusal (UNAUTHENTICATED / PERMISSION_DENIED).
using StatusAuthorizer =
    std::function<Status(std::optional<std::string_view> authorization)>;

struct StatusSources {
  // Null: /api/stats and /api/edges are public (--http-public-status).
  StatusAuthorizer authorize;
  StatsSource stats;
  EdgeSource edges;
  HistorySource history;
  // The /metrics body.
  std::function<std::string()> metrics_text;
};

class StatusEndpoints {
 public:
  explicit StatusEndpoints(StatusSources sources);

  // The response for a GET of `path` with the query string `query` and the
  // Authorization header `authorization`.
  HttpResponse Handle(
      std::string_view path, std::string_view query = {},
      std::optional<std::string_view> authorization = std::nullopt) const;

 private:
  // The response for an /api/ path about `dataset`, or 404 for another
  // path.
  HttpResponse Api(std::string_view path, std::string_view dataset,
                   std::optional<std::string_view> authorization) const;

  const StatusSources sources_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATUS_ENDPOINTS_H_
