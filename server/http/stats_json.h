// The JSON documents of the status API (/api/stats, /api/edges). Field
// names follow locator.v1's GetStatsResponse where they overlap.
//
// Thread-safety: free functions over values.

#ifndef LOCATOR_SERVER_HTTP_STATS_JSON_H_
#define LOCATOR_SERVER_HTTP_STATS_JSON_H_

#include <array>
#include <string>
#include <vector>

#include "server/core/engine.h"
#include "server/http/stats_history.h"

namespace locator {

// {"state": "serving", "dataset": {...}, "strategy", "queries",
//  "mean_cost_lifetime", "mean_cost_recent", "qps", "tuning": {...},
//  "history": {"t": [...], "qps": [...], "mean_cost": [...]}}; "qps" is the
// latest sample's (null before the first).
std::string StatsJson(const EngineStats& stats,
                      const std::vector<StatsSample>& history);

// {"state": "loading"}: no engine serves yet.
std::string LoadingJson();

// {"segments": [[x0, y0, x1, y1], ...]}.
std::string EdgesJson(const std::vector<std::array<Point2, 2>>& edges);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATS_JSON_H_
