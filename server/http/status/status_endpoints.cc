#include "server/http/status/status_endpoints.h"

#include <utility>

#include "common/json_writer.h"
#include "common/proto_json.h"
#include "server/http/api_error.h"
#include "server/http/embedded_files.h"
#include "server/http/query_string.h"
#include "server/metrics/metrics_text.h"

namespace locator {
namespace {

constexpr std::string_view kWebPrefix = "/web/";

// What an /api/ path answers when its source failed: 503
// {"state":"loading"} while the dataset loads, an ApiError otherwise (an
// unknown dataset: 404).
HttpResponse Failed(const Status& status) {
  if (status.code() == Status::Code::kUnavailable) {
    return HttpResponse{503, kJsonContentType, R"({"state":"loading"})"};
  }
  return ApiError(status);
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

// The file of `files` named `name`, or 404.
HttpResponse FileOf(std::span<const EmbeddedFile> files, std::string_view name);

// The Content-Type of an embedded file, by its extension.
std::string ContentTypeOf(std::string_view name) {
  const auto ends_with = [name](std::string_view suffix) {
    return name.size() >= suffix.size() &&
           name.substr(name.size() - suffix.size()) == suffix;
  };
  if (ends_with(".html")) return "text/html; charset=utf-8";
  if (ends_with(".js")) return "text/javascript; charset=utf-8";
  if (ends_with(".css")) return "text/css; charset=utf-8";
  if (ends_with(".txt")) return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

HttpResponse FileOf(std::span<const EmbeddedFile> files,
                    std::string_view name) {
  for (const EmbeddedFile& file : files) {
    if (name == file.name) {
      return HttpResponse{200, ContentTypeOf(file.name),
                          std::string(file.bytes)};
    }
  }
  return NotFound();
}

}  // namespace

StatusEndpoints::StatusEndpoints(StatusSources sources)
    : sources_(std::move(sources)) {}

HttpResponse StatusEndpoints::Handle(
    std::string_view path, std::string_view query,
    std::optional<std::string_view> authorization) const {
  if (path == "/metrics") {
    return HttpResponse{200, kMetricsContentType, sources_.metrics_text()};
  }
  if (path.starts_with("/api/")) {
    return Api(path, QueryParameter(query, "dataset"), authorization);
  }
  if (path == kWebPrefix.substr(0, kWebPrefix.size() - 1)) {
    // Its files name each other relative to the directory.
    return HttpResponse{.status = 301,
                        .body = "see /web/\n",
                        .headers = {{"Location", std::string(kWebPrefix)}}};
  }
  if (path.starts_with(kWebPrefix)) {
    const std::string_view name = path.substr(kWebPrefix.size());
    return FileOf(WebExampleFiles(), name.empty() ? "index.html" : name);
  }
  if (!path.starts_with('/')) return NotFound();
  return FileOf(StatusPageFiles(), path == "/" ? "index.html" : path.substr(1));
}

HttpResponse StatusEndpoints::Api(
    std::string_view path, std::string_view dataset,
    std::optional<std::string_view> authorization) const {
  if ((path == "/api/stats" || path == "/api/edges") && sources_.authorize) {
    if (Status refused = sources_.authorize(authorization); !refused.ok()) {
      return ApiError(refused);
    }
  }
  if (path == "/api/stats") {
    v1::GetStatsResponse stats;
    const Status status = sources_.stats(dataset, &stats);
    if (!status.ok()) return Failed(status);
    return HttpResponse{200, kJsonContentType, ProtoJson(stats)};
  }
  if (path == "/api/history") {
    const StatsHistory* history = nullptr;
    const Status status = sources_.history(dataset, &history);
    if (!status.ok()) return Failed(status);
    return HttpResponse{200, kJsonContentType, HistoryJson(history->Samples())};
  }
  if (path == "/api/edges") {
    MapEdges edges;
    const Status status = sources_.edges(dataset, &edges);
    if (!status.ok()) return Failed(status);
    return HttpResponse{200, kJsonContentType, EdgesJson(edges)};
  }
  return NotFound();
}

}  // namespace locator
