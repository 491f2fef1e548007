#include "server/metrics/engine_collector.h"

#include <limits>
#include <string>
#include <utility>

namespace locator {
namespace {

using prometheus::ClientMetric;
using prometheus::MetricFamily;
using prometheus::MetricType;

// The series of one metric family, one per dataset that has a value.
class Family {
 public:
  Family(std::string name, std::string help, MetricType type)
      : family_{std::move(name), std::move(help), type, {}} {}

  // Adds dataset `dataset`'s series, valued `value`.
  void Add(const std::string& dataset, double value) {
    ClientMetric metric;
    if (family_.type == MetricType::Counter) {
      metric.counter.value = value;
    } else {
      metric.gauge.value = value;
    }
    Add(dataset, std::move(metric));
  }
  // Adds dataset `dataset`'s series, `metric`.
  void Add(const std::string& dataset, ClientMetric metric) {
    metric.label.push_back({"dataset", dataset});
    family_.metric.push_back(std::move(metric));
  }

  MetricFamily Release() { return std::move(family_); }

 private:
  MetricFamily family_;
};

ClientMetric WalkFaces(const v1::WalkFacesHistogram& walks) {
  ClientMetric metric;
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
  return metric;
}

}  // namespace

EngineCollector::EngineCollector(AllStatsSource stats)
    : stats_(std::move(stats)) {}

std::vector<MetricFamily> EngineCollector::Collect() const {
  Family loaded("locator_engine_loaded",
                "1 once a dataset's engine serves, else 0", MetricType::Gauge);
  Family queries("locator_queries_total",
                 "Points located by the dataset's current engine",
                 MetricType::Counter);
  Family cost("locator_query_cost_total",
              "Summed cost of the located points "
              "(faces + comparisons + table lookups)",
              MetricType::Counter);
  Family mean_cost("locator_mean_cost_recent",
                   "Mean cost over the last completed window of 1000 queries",
                   MetricType::Gauge);
  Family walk_faces("locator_walk_faces",
                    "Faces visited by the walk per located query",
                    MetricType::Histogram);
  Family hot("locator_hot_region_queries_total",
             "Self-tuning: queries answered in cells tuned as hot",
             MetricType::Counter);
  Family fallback("locator_fallback_queries_total",
                  "Self-tuning: queries answered in cold cells",
                  MetricType::Counter);
  Family retunes("locator_retunes_total", "Re-tunes done", MetricType::Counter);
  Family snapshot("locator_snapshot_version",
                  "Version of the published tuning snapshot",
                  MetricType::Gauge);
  Family starts("locator_start_points", "Start points in use",
                MetricType::Gauge);
  Family triangulation_bytes("locator_triangulation_bytes",
                             "Memory of the triangulation", MetricType::Gauge);
  Family tuning_bytes("locator_tuning_bytes", "Memory of the tuning structures",
                      MetricType::Gauge);
  Family vertices("locator_dataset_vertices", "Distinct points of the dataset",
                  MetricType::Gauge);
  Family triangles("locator_dataset_triangles",
                   "Triangles served (in the dataset's domain)",
                   MetricType::Gauge);

  for (const DatasetStatsSample& sample : stats_()) {
    const std::string& name = sample.dataset;
    loaded.Add(name, sample.stats ? 1 : 0);
    if (!sample.stats) continue;
    const v1::GetStatsResponse& stats = *sample.stats;
    const v1::TuningStats& tuning = stats.tuning();
    const auto as_double = [](uint64_t value) {
      return static_cast<double>(value);
    };
    queries.Add(name, as_double(stats.queries_served()));
    cost.Add(name, as_double(stats.total_cost()));
    mean_cost.Add(name, stats.mean_cost_recent());
    walk_faces.Add(name, WalkFaces(stats.walk_faces()));
    hot.Add(name, as_double(tuning.hot_queries()));
    fallback.Add(name, as_double(tuning.fallback_queries()));
    retunes.Add(name, as_double(tuning.retune_count()));
    snapshot.Add(name, as_double(tuning.snapshot_version()));
    starts.Add(name, as_double(tuning.start_point_count()));
    triangulation_bytes.Add(name,
                            as_double(stats.memory().triangulation_bytes()));
    tuning_bytes.Add(name, as_double(stats.memory().tuning_bytes()));
    vertices.Add(name, as_double(stats.dataset().vertices()));
    triangles.Add(name, as_double(stats.dataset().triangles()));
  }
  std::vector<MetricFamily> families;
  for (Family* family :
       {&loaded, &queries, &cost, &mean_cost, &walk_faces, &hot, &fallback,
        &retunes, &snapshot, &starts, &triangulation_bytes, &tuning_bytes,
        &vertices, &triangles}) {
    MetricFamily released = family->Release();
    if (!released.metric.empty()) families.push_back(std::move(released));
  }
  return families;
}

}  // namespace locator
