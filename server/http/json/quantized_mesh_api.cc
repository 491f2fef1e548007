// The HTTP routes of the Cesium terrain
// (server/tiles/quantized_mesh/quantized_mesh_tile.h):
//
//   GET /v1/datasets/{name}/quantized-mesh/layer.json
//   GET /v1/datasets/{name}/quantized-mesh/{z}/{x}/{y}.terrain
//
// admitted as every dataset method is (LocatorApp::Admit) and run in the
// expensive lane (a tile cuts, maps and simplifies a piece of the TIN), the
// layer.json in the cheap one. A tile is application/vnd.quantized-mesh,
// to an Accept that takes it (or application/octet-stream, or any type;
// CesiumJS sends all three), else 406; gzipped (Content-Encoding: gzip,
// Vary: Accept-Encoding) when Accept-Encoding takes gzip. Both carry an
// ETag (TileETag: the dataset's generation; the gzipped and plain tiles
// have their own) and Cache-Control as the PNG tiles do, and answer 304
// without rendering to an If-None-Match that names the ETag. The `v` that
// layer.json puts in the tiles' URLs is the generation's tag, so a reload
// changes every URL.

#include <array>
#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "server/http/api_error.h"
#include "server/http/json/api_answers.h"
#include "server/http/json/json_api.h"
#include "server/tiles/quantized_mesh/gzip_body.h"
#include "server/tiles/quantized_mesh/quantized_mesh_tile.h"
#include "server/tiles/terrain_tile.h"

namespace locator {
namespace {

constexpr std::string_view kLayerJsonPath = "layer.json";
constexpr std::string_view kTerrainSuffix = ".terrain";
constexpr std::string_view kMeshType = "application/vnd.quantized-mesh";

// The comma-separated items of a header value, each without its
// parameters (";q=...", ";extensions=...") and surrounding blanks, with
// whether its q is 0 (refused).
template <typename Visit>
void ForEachItem(std::string_view header, Visit visit) {
  while (!header.empty()) {
    const size_t comma = header.find(',');
    std::string_view item = header.substr(0, comma);
    const size_t semicolon = item.find(';');
    std::string_view parameters =
        semicolon == std::string_view::npos ? "" : item.substr(semicolon);
    item = item.substr(0, semicolon);
    while (!item.empty() && (item.front() == ' ' || item.front() == '\t')) {
      item.remove_prefix(1);
    }
    while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) {
      item.remove_suffix(1);
    }
    // q=0 (0.0, 0.00...) refuses the item.
    const size_t q = parameters.find("q=");
    double weight = 1;
    if (q != std::string_view::npos) {
      const char* begin = parameters.data() + q + 2;
      std::from_chars(begin, parameters.data() + parameters.size(), weight);
    }
    const bool refused = weight == 0;
    visit(item, refused);
    if (comma == std::string_view::npos) break;
    header.remove_prefix(comma + 1);
  }
}

// Whether an Accept value takes a quantized-mesh tile.
bool AcceptsMesh(std::string_view accept) {
  bool takes = false;
  ForEachItem(accept, [&](std::string_view type, bool refused) {
    if (refused) return;
    takes |= type == kMeshType || type == "application/octet-stream" ||
             type == "application/*" || type == "*/*";
  });
  return takes;
}

// Whether an Accept-Encoding value takes gzip.
bool AcceptsGzip(std::string_view accept_encoding) {
  bool takes = false;
  ForEachItem(accept_encoding, [&](std::string_view coding, bool refused) {
    takes |= !refused && (coding == "gzip" || coding == "*");
  });
  return takes;
}

}  // namespace

void JsonApi::ServeQuantizedMesh(HttpRequest request, std::string name,
                                 std::string rest, HttpReply reply) {
  const bool layer_json = rest == kLayerJsonPath;
  std::array<std::string_view, 3> zxy;
  if (!layer_json &&
      !(rest.ends_with(kTerrainSuffix) &&
        SplitTilePath(std::string_view(rest).substr(
                          0, rest.size() - kTerrainSuffix.size()),
                      &zxy))) {
    reply(NoRoute(request));
    return;
  }
  // The deadline runs from the call's arrival: time queued counts.
  const CallDeadline deadline = app_->DefaultDeadline();
  std::optional<LocatorApp::Admission> call =
      AdmitTileGet(request, name, reply);
  if (!call.has_value()) return;
  GeographicTile tile;
  bool gzip = false;
  if (!layer_json) {
    StatusOr<GeographicTile> parsed =
        ParseGeographicTile(zxy[0], zxy[1], zxy[2]);
    if (!parsed.ok()) {
      reply(ApiError(parsed.status()));
      return;
    }
    tile = *parsed;
    const std::optional<std::string_view> accept = request.Header("accept");
    if (accept.has_value() && !accept->empty() && !AcceptsMesh(*accept)) {
      reply(ApiError(
          Status::InvalidArgument("a tile is " + std::string(kMeshType) +
                                  ", which the request's Accept does not take"),
          406));
      return;
    }
    gzip = AcceptsGzip(request.Header("accept-encoding").value_or(""));
  }
  std::vector<std::pair<std::string, std::string>> headers = {
      {"ETag", TileETag(call->generation, layer_json ? "layer"
                                          : gzip     ? "mesh-gzip"
                                                     : "mesh")},
      {"Cache-Control", TileCacheControl()}};
  if (!layer_json) headers.emplace_back("Vary", "Accept-Encoding");
  if (const std::optional<std::string_view> match =
          request.Header("if-none-match");
      match.has_value() && NamesETag(*match, headers[0].second)) {
    reply(HttpResponse{.status = 304, .body = "", .headers = headers});
    return;
  }
  // The version in the tiles' URLs: the generation's tag, unquoted.
  const std::string version = [&] {
    const std::string tag = TileETag(call->generation, "mesh");
    return tag.substr(1, tag.size() - 2);
  }();
  RunInLane(
      layer_json ? cheap_ : expensive_, deadline, std::move(reply),
      [call = *std::move(call), name = std::move(name), tile, layer_json, gzip,
       version, headers = std::move(headers)](HttpReply reply) mutable {
        const Engine& engine = *call.engine;
        StatusOr<std::string> body =
            layer_json ? LayerJson(engine, name, version)
                       : RenderQuantizedMesh(engine, name, tile);
        if (body.ok() && gzip) body = GzipBody(*body);
        if (!body.ok()) {
          reply(ApiError(body.status()));
          return;
        }
        if (gzip) headers.emplace_back("Content-Encoding", "gzip");
        reply(HttpResponse{.content_type = layer_json
                                               ? std::string(kJsonContentType)
                                               : std::string(kMeshType),
                           .body = *std::move(body),
                           .headers = std::move(headers)});
      });
}

}  // namespace locator
