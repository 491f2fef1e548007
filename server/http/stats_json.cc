#include "server/http/stats_json.h"

#include <limits>

#include "server/http/json_writer.h"

namespace locator {
namespace {

void WriteBox(const BoundingBox& box, JsonWriter* json) {
  json->BeginObject()
      .Key("min_x")
      .Number(box.min_x)
      .Key("min_y")
      .Number(box.min_y)
      .Key("max_x")
      .Number(box.max_x)
      .Key("max_y")
      .Number(box.max_y)
      .EndObject();
}

void WriteDataset(const DatasetInfo& info, JsonWriter* json) {
  json->BeginObject()
      .Key("source")
      .String(info.source)
      .Key("input_points")
      .Integer(info.input_points)
      .Key("vertices")
      .Integer(info.vertices)
      .Key("duplicates_merged")
      .Integer(info.duplicates_merged)
      .Key("triangles")
      .Integer(info.triangles)
      .Key("has_values")
      .Bool(info.has_values)
      .Key("triangulation_bytes")
      .Integer(info.triangulation_bytes)
      .Key("build_seconds")
      .Number(info.build_seconds)
      .Key("bounding_box");
  WriteBox(info.bounding_box, json);
  json->EndObject();
}

void WriteTuning(const TuningSummary& tuning, JsonWriter* json) {
  json->BeginObject()
      .Key("snapshot_version")
      .Integer(tuning.snapshot_version)
      .Key("retune_count")
      .Integer(tuning.retune_count)
      .Key("memory_bytes")
      .Integer(tuning.memory_bytes)
      .Key("hot_queries")
      .Integer(tuning.hot_queries)
      .Key("fallback_queries")
      .Integer(tuning.fallback_queries)
      .Key("start_point_count")
      .Integer(tuning.start_point_count)
      .Key("grid_size")
      .Integer(static_cast<uint64_t>(tuning.grid_size))
      .Key("grid_box");
  WriteBox(tuning.grid_box, json);
  json->Key("histogram").BeginArray();
  for (double count : tuning.histogram) json->Number(count);
  json->EndArray().Key("hot_regions").BeginArray();
  for (const BoundingBox& region : tuning.hot_regions) WriteBox(region, json);
  json->EndArray().Key("start_points").BeginArray();
  for (const Point2& p : tuning.start_points) {
    json->BeginArray().Number(p.x).Number(p.y).EndArray();
  }
  json->EndArray().EndObject();
}

void WriteHistory(const std::vector<StatsSample>& history, JsonWriter* json) {
  json->BeginObject().Key("t").BeginArray();
  for (const StatsSample& s : history) json->Number(s.unix_seconds);
  json->EndArray().Key("qps").BeginArray();
  for (const StatsSample& s : history) json->Number(s.qps);
  json->EndArray().Key("mean_cost").BeginArray();
  for (const StatsSample& s : history) json->Number(s.mean_cost);
  json->EndArray().EndObject();
}

}  // namespace

std::string StatsJson(const EngineStats& stats,
                      const std::vector<StatsSample>& history) {
  JsonWriter json;
  json.BeginObject().Key("state").String("serving").Key("dataset");
  WriteDataset(stats.dataset, &json);
  json.Key("strategy")
      .String(stats.strategy)
      .Key("queries")
      .Integer(stats.queries)
      .Key("mean_cost_lifetime")
      .Number(stats.mean_cost_lifetime)
      .Key("mean_cost_recent")
      .Number(stats.mean_cost_recent)
      .Key("qps")
      .Number(history.empty() ? std::numeric_limits<double>::quiet_NaN()
                              : history.back().qps)
      .Key("tuning");
  WriteTuning(stats.tuning, &json);
  json.Key("history");
  WriteHistory(history, &json);
  json.EndObject();
  return json.text();
}

std::string LoadingJson() {
  JsonWriter json;
  json.BeginObject().Key("state").String("loading").EndObject();
  return json.text();
}

std::string EdgesJson(const std::vector<std::array<Point2, 2>>& edges) {
  JsonWriter json;
  json.BeginObject().Key("segments").BeginArray();
  for (const auto& [a, b] : edges) {
    json.BeginArray()
        .Number(a.x)
        .Number(a.y)
        .Number(b.x)
        .Number(b.y)
        .EndArray();
  }
  json.EndArray().EndObject();
  return json.text();
}

}  // namespace locator
