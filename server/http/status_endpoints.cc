#include "server/http/status_endpoints.h"

#include <utility>

#include "server/http/stats_json.h"
#include "server/http/status_page_files.h"

namespace locator {
namespace {

constexpr char kJson[] = "application/json";
constexpr char kMetricsContentType[] =
    "text/plain; version=0.0.4; charset=utf-8";

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
  if (path != "/api/stats" && path != "/api/edges") return NotFound();
  const std::shared_ptr<Engine> engine = sources_.current_engine();
  if (engine == nullptr) return HttpResponse{503, kJson, LoadingJson()};
  if (path == "/api/edges") {
    return HttpResponse{200, kJson, EdgesJson(engine->EdgeSample())};
  }
  return HttpResponse{200, kJson,
                      StatsJson(engine->Stats(), sources_.history->Samples())};
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
