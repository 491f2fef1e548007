// EngineCollector: Prometheus metrics of the datasets' serving engines,
// read at scrape time from their statistics as GetStats answers them (the
// one mapping of the engine's statistics, already redacted as configured),
// so they follow whichever engine each dataset serves (a Reload may swap it;
// counters then restart, which Prometheus treats as a reset). Every series
// carries the label dataset="NAME".
//
//   locator_engine_loaded                  1 once the dataset serves, else 0
//   locator_queries_total                  points located
//   locator_query_cost_total               their summed cost (paper metric)
//   locator_mean_cost_recent               mean cost, last 1000 queries
//   locator_walk_faces                     histogram: faces visited per query
//   locator_hot_region_queries_total       self-tuning: answered in hot cells
//   locator_fallback_queries_total         self-tuning: in cold cells
//   locator_retunes_total                  re-tunes done
//   locator_snapshot_version               published tuning snapshot
//   locator_start_points                   start points in use
//   locator_triangulation_bytes            memory of the triangulation
//   locator_tuning_bytes                   memory of the tuning structures
//   locator_dataset_vertices, locator_dataset_triangles
//
// Owns only the function that yields the statistics.
// Thread-safety: Collect() may be called from any thread.

#ifndef LOCATOR_SERVER_METRICS_ENGINE_COLLECTOR_H_
#define LOCATOR_SERVER_METRICS_ENGINE_COLLECTOR_H_

#include <prometheus/collectable.h>
#include <prometheus/metric_family.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "locator/v1/locator.pb.h"

namespace locator {

// One dataset's statistics as GetStats answers them; none while it loads.
struct DatasetStatsSample {
  std::string dataset;
  std::optional<v1::GetStatsResponse> stats;
};

// Every dataset's statistics, in the server's order.
using AllStatsSource = std::function<std::vector<DatasetStatsSample>()>;

class EngineCollector final : public prometheus::Collectable {
 public:
  // `stats` is called once per Collect().
  explicit EngineCollector(AllStatsSource stats);

  // The series listed above from one call of the stats source.
  std::vector<prometheus::MetricFamily> Collect() const override;

 private:
  const AllStatsSource stats_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_METRICS_ENGINE_COLLECTOR_H_
