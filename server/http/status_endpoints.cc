#include "server/http/status_endpoints.h"

#include <utility>

#include "common/proto_json.h"
#include "server/http/json_writer.h"
#include "server/http/status_page_files.h"

namespace locator {
namespace {

constexpr char kJson[] = "application/json";
constexpr char kMetricsContentType[] =
    "text/plain; version=0.0.4; charset=utf-8";

HttpResponse Loading() {
  return HttpResponse{503, kJson, R"({"state":"loading"})"};
}

std::string HistoryJson(const std::vector<StatsSample>& history) {
  JsonWriter json;
  json.BeginObject().Key("t").BeginArray();
  for (const StatsSample& s : history) json.Number(s.unix_seconds);
  json.EndArray().Key("qps").BeginArray();
  for (const StatsSample& s : history) json.Number(s.qps);
  json.EndArray().Key("mean_cost").BeginArray();
  for (const StatsSample& s : history) json.Number(s.mean_cost);
  json.EndArray().EndObject();
  return json.text();
}

// `segments` as the value of `key`: [[x0, y0, x1, y1], ...].
void SegmentsJson(const char* key,
                  const std::vector<std::array<Point2, 2>>& segments,
                  JsonWriter* json) {
  json->Key(key).BeginArray();
  for (const auto& [a, b] : segments) {
    json->BeginArray()
        .Number(a.x)
        .Number(a.y)
        .Number(b.x)
        .Number(b.y)
        .EndArray();
  }
  json->EndArray();
}

std::string EdgesJson(const MapEdges& edges) {
  JsonWriter json;
  json.BeginObject();
  SegmentsJson("segments", edges.segments, &json);
  SegmentsJson("boundary", edges.boundary, &json);
  SegmentsJson("breaklines", edges.breaklines, &json);
  json.EndObject();
  return json.text();
}

HttpResponse NotFound() {
  return HttpResponse{404, "text/plain; charset=utf-8", "not found\n"};
}

// The Content-Type of an embedded file, by its extension.
std::string ContentTypeOf(std::string_view name) {
  const auto ends_with = [name](std::string_view suffix) {
    return name.size() >= suffix.size() &&
           name.substr(name.size() - suffix.size()) == suffix;
  };
  if (ends_with(".html")) return "text/html; charset=utf-8";
  if (ends_with(".js")) return "text/javascript; charset=utf-8";
  if (ends_with(".css")) return "text/css; charset=utf-8";
  return "application/octet-stream";
}

}  // namespace

StatusEndpoints::StatusEndpoints(StatusSources sources)
    : sources_(std::move(sources)) {}

HttpResponse StatusEndpoints::Handle(std::string_view path) const {
  if (path == "/metrics") {
    return HttpResponse{200, kMetricsContentType, sources_.metrics_text()};
  }
  if (path.starts_with("/api/")) return Api(path);
  return PageFile(path == "/" ? "/index.html" : path);
}

HttpResponse StatusEndpoints::Api(std::string_view path) const {
  if (path == "/api/stats") {
    v1::GetStatsResponse stats;
    if (!sources_.stats(&stats)) return Loading();
    return HttpResponse{200, kJson, ProtoJson(stats)};
  }
  if (path == "/api/history") {
    return HttpResponse{200, kJson, HistoryJson(sources_.history->Samples())};
  }
  if (path == "/api/edges") {
    MapEdges edges;
    if (!sources_.edges(&edges)) return Loading();
    return HttpResponse{200, kJson, EdgesJson(edges)};
  }
  return NotFound();
}

HttpResponse StatusEndpoints::PageFile(std::string_view path) {
  if (!path.starts_with('/')) return NotFound();
  for (const EmbeddedFile& file : StatusPageFiles()) {
    if (path.substr(1) == file.name) {
      return HttpResponse{200, ContentTypeOf(file.name),
                          std::string(file.bytes)};
    }
  }
  return NotFound();
}

}  // namespace locator
