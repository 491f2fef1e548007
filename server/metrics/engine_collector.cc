#include "server/metrics/engine_collector.h"

#include <limits>
#include <string>
#include <utility>

namespace locator {
namespace {

prometheus::MetricFamily OneValue(std::string name, std::string help,
                                  prometheus::MetricType type, double value) {
  prometheus::ClientMetric metric;
  if (type == prometheus::MetricType::Counter) {
    metric.counter.value = value;
  } else {
    metric.gauge.value = value;
  }
  return {std::move(name), std::move(help), type, {metric}};
}

prometheus::MetricFamily Counter(std::string name, std::string help,
                                 double value) {
  return OneValue(std::move(name), std::move(help),
                  prometheus::MetricType::Counter, value);
}

prometheus::MetricFamily Gauge(std::string name, std::string help,
                               double value) {
  return OneValue(std::move(name), std::move(help),
                  prometheus::MetricType::Gauge, value);
}

prometheus::MetricFamily WalkFaces(const v1::WalkFacesHistogram& walks) {
  prometheus::ClientMetric metric;
  uint64_t cumulative = 0;
  for (int i = 0; i < walks.counts_size(); ++i) {
    cumulative += walks.counts(i);
    const double bound = i < walks.upper_bounds_size()
                             ? walks.upper_bounds(i)
                             : std::numeric_limits<double>::infinity();
    metric.histogram.bucket.push_back({cumulative, bound});
  }
  metric.histogram.sample_count = cumulative;
  metric.histogram.sample_sum = static_cast<double>(walks.faces_sum());
  return {"locator_walk_faces",
          "Faces visited by the walk per located query",
          prometheus::MetricType::Histogram,
          {metric}};
}

}  // namespace

EngineCollector::EngineCollector(StatsSource stats)
    : stats_(std::move(stats)) {}

std::vector<prometheus::MetricFamily> EngineCollector::Collect() const {
  v1::GetStatsResponse stats;
  const bool loaded = stats_(&stats);
  std::vector<prometheus::MetricFamily> families;
  families.push_back(Gauge("locator_engine_loaded",
                           "1 once a dataset's engine serves, else 0",
                           loaded ? 1 : 0));
  if (!loaded) return families;
  const v1::TuningStats& tuning = stats.tuning();
  families.push_back(Counter("locator_queries_total",
                             "Points located by the current engine",
                             static_cast<double>(stats.queries_served())));
  families.push_back(Counter("locator_query_cost_total",
                             "Summed cost of the located points "
                             "(faces + comparisons + table lookups)",
                             static_cast<double>(stats.total_cost())));
  families.push_back(Gauge("locator_mean_cost_recent",
                           "Mean cost over the last completed window of "
                           "1000 queries",
                           stats.mean_cost_recent()));
  families.push_back(WalkFaces(stats.walk_faces()));
  families.push_back(Counter("locator_hot_region_queries_total",
                             "Self-tuning: queries answered in cells tuned "
                             "as hot",
                             static_cast<double>(tuning.hot_queries())));
  families.push_back(Counter("locator_fallback_queries_total",
                             "Self-tuning: queries answered in cold cells",
                             static_cast<double>(tuning.fallback_queries())));
  families.push_back(Counter("locator_retunes_total", "Re-tunes done",
                             static_cast<double>(tuning.retune_count())));
  families.push_back(Gauge("locator_snapshot_version",
                           "Version of the published tuning snapshot",
                           static_cast<double>(tuning.snapshot_version())));
  families.push_back(Gauge("locator_start_points", "Start points in use",
                           static_cast<double>(tuning.start_point_count())));
  families.push_back(
      Gauge("locator_triangulation_bytes", "Memory of the triangulation",
            static_cast<double>(stats.memory().triangulation_bytes())));
  families.push_back(Gauge("locator_tuning_bytes",
                           "Memory of the tuning structures",
                           static_cast<double>(stats.memory().tuning_bytes())));
  families.push_back(Gauge("locator_dataset_vertices",
                           "Distinct points of the dataset",
                           static_cast<double>(stats.dataset().vertices())));
  families.push_back(Gauge("locator_dataset_triangles",
                           "Finite triangles of the triangulation",
                           static_cast<double>(stats.dataset().triangles())));
  return families;
}

}  // namespace locator
