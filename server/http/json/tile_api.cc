// The HTTP routes of the terrain tiles (server/tiles/terrain_tile.h) and
// the hillshade tiles (server/tiles/hillshade.h):
//
//   GET /v1/datasets/{name}/tiles/{z}/{x}/{y}.png?encoding=terrarium|mapbox
//   GET /v1/datasets/{name}/tiles.json?encoding=terrarium|mapbox
//   GET /v1/datasets/{name}/hillshade/{z}/{x}/{y}.png?azimuth=&altitude=
//       &z_factor=&scale=
//
// admitted as every dataset method is (LocatorApp::Admit: the drain, the
// data token, the dataset) and run in the expensive lane (a tile walks
// 65536 pixels). All carry an ETag (TileETag: the dataset's generation and
// the encoding or the light) and Cache-Control, and answer 304 without
// rendering to an If-None-Match that names the ETag. Tiles of a server that
// wants a token are "private", so that no shared cache hands them to someone
// without one.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "server/http/api_error.h"
#include "server/http/json/api_answers.h"
#include "server/http/json/json_api.h"
#include "server/http/query_string.h"
#include "server/tiles/hillshade.h"
#include "server/tiles/terrain_tile.h"

namespace locator {
namespace {

constexpr std::string_view kTilesPrefix = "/tiles/";
constexpr std::string_view kHillshadePrefix = "/hillshade/";
constexpr std::string_view kTileJsonPath = "/tiles.json";
constexpr std::string_view kPngSuffix = ".png";
// How long a browser may use a tile without asking again: a reload shows
// within a minute, and a map panning back and forth does not ask twice.
constexpr std::string_view kMaxAge = "max-age=60";

// The URL template of the tiles of dataset `name` that a TileJSON fetched
// by `request` points to: absolute when the request names a plausible Host
// (behind a proxy that says X-Forwarded-Proto: https, an https one), else
// the path alone, which a page of the same origin resolves.
std::string TilesUrl(const HttpRequest& request, std::string_view name,
                     std::string_view encoding) {
  std::string url = std::string(JsonApi::kPathPrefix) + "datasets/" +
                    std::string(name) +
                    "/tiles/{z}/{x}/{y}.png?encoding=" + std::string(encoding);
  const std::optional<std::string_view> host = request.Header("host");
  constexpr std::string_view kHostCharacters =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.-:[]";
  if (!host.has_value() || host->empty() || host->size() > 255 ||
      host->find_first_not_of(kHostCharacters) != std::string_view::npos) {
    return url;
  }
  const bool https = request.Header("x-forwarded-proto") == "https";
  return (https ? "https://" : "http://") + std::string(*host) + url;
}

}  // namespace

bool JsonApi::SplitTilePath(std::string_view zxy,
                            std::array<std::string_view, 3>* parts) {
  const size_t first = zxy.find('/');
  const size_t second = first == std::string_view::npos
                            ? std::string_view::npos
                            : zxy.find('/', first + 1);
  if (second == std::string_view::npos ||
      zxy.find('/', second + 1) != std::string_view::npos) {
    return false;
  }
  *parts = {zxy.substr(0, first), zxy.substr(first + 1, second - first - 1),
            zxy.substr(second + 1)};
  return true;
}

std::string JsonApi::TileCacheControl() const {
  return std::string(app_->access_policy()
                             .CheckAuthorization(std::nullopt,
                                                 AccessPolicy::Scope::kData)
                             .ok()
                         ? "public, "
                         : "private, ") +
         std::string(kMaxAge);
}

std::optional<LocatorApp::Admission> JsonApi::AdmitTileGet(
    const HttpRequest& request, const std::string& name,
    HttpReply& reply) const {
  if (request.method != "GET") {
    reply(MethodNotAllowed(request, "GET"));
    return std::nullopt;
  }
  StatusOr<LocatorApp::Admission> call = app_->Admit(
      request.Header("authorization"), AccessPolicy::Scope::kData, name);
  if (!call.ok()) {
    reply(ApiError(call.status()));
    return std::nullopt;
  }
  return *std::move(call);
}

void JsonApi::ServeTiles(HttpRequest request, std::string name,
                         std::string rest, HttpReply reply) {
  const bool tile_json = rest == kTileJsonPath;
  const bool png = rest.ends_with(kPngSuffix);
  const bool terrain = png && rest.starts_with(kTilesPrefix);
  const bool hillshade = png && rest.starts_with(kHillshadePrefix);
  if (!tile_json && !terrain && !hillshade) {
    reply(NoRoute(request));
    return;
  }
  // The deadline runs from the call's arrival: time queued counts.
  const CallDeadline deadline = app_->DefaultDeadline();
  std::optional<LocatorApp::Admission> call =
      AdmitTileGet(request, name, reply);
  if (!call.has_value()) return;
  // What the tiles show: a terrain encoding, or the light of the relief.
  TerrainEncoding encoding = TerrainEncoding::kTerrarium;
  HillshadeOptions light;
  std::string variant;
  if (hillshade) {
    StatusOr<HillshadeOptions> parsed =
        ParseHillshadeOptions(QueryParameter(request.query, "azimuth"),
                              QueryParameter(request.query, "altitude"),
                              QueryParameter(request.query, "z_factor"),
                              QueryParameter(request.query, "scale"));
    if (!parsed.ok()) {
      reply(ApiError(parsed.status()));
      return;
    }
    light = *parsed;
    variant = HillshadeVariant(light);
  } else {
    const StatusOr<TerrainEncoding> parsed =
        ParseTerrainEncoding(QueryParameter(request.query, "encoding"));
    if (!parsed.ok()) {
      reply(ApiError(parsed.status()));
      return;
    }
    encoding = *parsed;
    variant = TerrainEncodingName(encoding);
  }
  TileAddress tile;
  if (!tile_json) {
    // "{prefix}{z}/{x}/{y}.png": three segments between the prefix and the
    // suffix.
    const std::string_view prefix = hillshade ? kHillshadePrefix : kTilesPrefix;
    std::array<std::string_view, 3> zxy;
    if (!SplitTilePath(
            std::string_view(rest).substr(
                prefix.size(), rest.size() - prefix.size() - kPngSuffix.size()),
            &zxy)) {
      reply(NoRoute(request));
      return;
    }
    StatusOr<TileAddress> parsed = ParseTileAddress(zxy[0], zxy[1], zxy[2]);
    if (!parsed.ok()) {
      reply(ApiError(parsed.status()));
      return;
    }
    tile = *parsed;
  }
  std::vector<std::pair<std::string, std::string>> headers = {
      {"ETag", TileETag(call->generation, variant)},
      {"Cache-Control", TileCacheControl()}};
  if (const std::optional<std::string_view> match =
          request.Header("if-none-match");
      match.has_value() && NamesETag(*match, headers[0].second)) {
    reply(HttpResponse{.status = 304, .body = "", .headers = headers});
    return;
  }
  RunInLane(tile_json ? cheap_ : expensive_, deadline, std::move(reply),
            [call = *std::move(call), request = std::move(request),
             name = std::move(name), encoding, light, hillshade, tile,
             tile_json, headers = std::move(headers)](HttpReply reply) mutable {
              const Engine& engine = *call.engine;
              StatusOr<std::string> body =
                  tile_json   ? TileJson(engine, name,
                                         TilesUrl(request, name,
                                                  TerrainEncodingName(encoding)),
                                         encoding)
                  : hillshade ? RenderHillshadeTile(engine, name, tile, light)
                              : RenderTerrainTile(engine, name, tile, encoding);
              if (!body.ok()) {
                reply(ApiError(body.status()));
                return;
              }
              reply(HttpResponse{
                  .content_type = tile_json ? kJsonContentType : "image/png",
                  .body = *std::move(body),
                  .headers = std::move(headers)});
            });
}

}  // namespace locator
