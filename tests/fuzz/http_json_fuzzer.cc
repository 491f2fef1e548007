// Fuzzes the HTTP/JSON API's request path: bytes -> an HTTP request to
// JsonApi (the first byte picks the route and method, the rest is the
// body) -> JSON parsing, admission, the service's Locate, LocateBatch,
// Profile or Grid on a small fixed dataset (or on "utm", the same points
// in UTM zone 33N with a CRS, so that request CRS strings reach PROJ) ->
// the JSON answer. The tile routes take the input as the rest of their
// path (and query) instead: /v1/datasets/utm/tiles/{input} or
// .../hillshade/{input}, answered with a PNG (or TileJSON) or an ApiError,
// and /v1/datasets/utm/quantized-mesh/{input}, answered with a
// quantized-mesh tile (or layer.json) or an ApiError. So do the elevation
// APIs' GET routes (Open Topo Data's query, EDR's position and trajectory
// queries and collection paths); Open Topo Data's POST takes it as its JSON
// body. Open Topo Data answers {"results", "status": "OK"} or its own error
// {"error", "status"}, 400 INVALID_REQUEST (never SERVER_ERROR); EDR a
// CoverageJSON, GeoJSON or JSON document, or an ApiError.
//
// Aborts unless every answer is one JSON object: on 200 the route's
// response message in protobuf's JSON mapping, otherwise an ApiError
// {"code", "status", "message"} whose HTTP status is the code's
// (HttpStatusForCanonicalCode; 405 for a wrong method), never INTERNAL or
// UNKNOWN (every fault is the caller's or a limit), with a non-empty message
// shorter than 1 KiB; unless a :locate body that protobuf parses, with a finite
// point and no other dataset, is answered 200 with the engine's own triangle,
// and every other :locate body 400 INVALID_ARGUMENT; and unless a :locateBatch
// answer has one entry per point, a :profile answer's breakpoints come in order
// with its crossings counted, and a :grid answer holds every cell its header
// announces.
//
// The seeds and dictionaries/http_json_fuzzer.dict hold issue 26's hostile
// values: 1e160, 1e300, DBL_MAX, denormals, NaN and infinities as JSON,
// sample counts past 32 bits, tiny cell sizes and CRS strings that name
// devices and files.

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <iterator>
#include <memory>
#include <string>
#include <string_view>

#include "common/gis/proj_objects.h"
#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "locator/v1/locator.pb.h"
#include "server/app/locator_app.h"
#include "server/http/api_error.h"
#include "server/http/edr/edr_api.h"
#include "server/http/json/json_api.h"
#include "server/http/opentopodata/open_topo_data_api.h"

namespace locator {
namespace {

// What the first input byte selects (modulo the count).
struct Route {
  const char* method;
  const char* path;
};
constexpr Route kRoutes[] = {
    {"POST", "/v1/datasets/default:locate"},
    {"POST", "/v1/datasets/default:locateBatch"},
    {"POST", "/v1/datasets/other:locate"},
    {"GET", "/v1/datasets"},
    {"GET", "/v1/datasets/default:locate"},
    {"POST", "/v1/datasets/nope:locate"},
    {"POST", "/v1/datasets/default:nope"},
    {"POST", "/v1/elsewhere"},
    {"POST", "/v1/datasets/default:profile"},
    {"POST", "/v1/datasets/default:grid"},
    {"POST", "/v1/datasets/utm:locate"},
    {"POST", "/v1/datasets/utm:locateBatch"},
    {"POST", "/v1/datasets/utm:profile"},
    // The input is the rest of the path (see FuzzOneInput).
    {"GET", "/v1/datasets/utm/tiles/"},
    {"GET", "/v1/datasets/utm/tiles"},
    {"GET", "/v1/datasets/default/tiles/"},
    {"GET", "/v1/datasets/utm/hillshade/"},
    // The elevation APIs: GETs take the input as their query (after '?'),
    // the POST as its body; EDR's collections as the rest of the path.
    {"GET", "/opentopodata/v1/utm"},
    {"POST", "/opentopodata/v1/utm"},
    {"GET", "/edr/collections/utm/position"},
    {"GET", "/edr/collections/utm/trajectory"},
    {"GET", "/edr/collections/"},
    {"GET", "/v1/datasets/utm/quantized-mesh/"},
    {"GET", "/v1/datasets/default/quantized-mesh/"},
};

[[noreturn]] void Fail(const std::string& what, const std::string& body) {
  std::fprintf(stderr, "http_json_fuzzer: %s\nanswer: %s\n", what.c_str(),
               body.c_str());
  std::abort();
}

// Whether `route` takes the input as the rest of its path.
bool IsTileRoute(const Route& route) {
  const std::string_view path = route.path;
  return path.find("/tiles") != std::string_view::npos ||
         path.find("/hillshade/") != std::string_view::npos ||
         path.find("/quantized-mesh/") != std::string_view::npos;
}

bool IsOpenTopoDataRoute(const Route& route) {
  return std::string_view(route.path).starts_with("/opentopodata/");
}

bool IsEdrRoute(const Route& route) {
  return std::string_view(route.path).starts_with("/edr/");
}

// Checks a 200 answer of a tile route: a PNG, a quantized-mesh tile (at
// least its header, vertex count, triangle count and four edge counts),
// or TileJSON (tiles.json, layer.json).
void CheckTileAnswer(const HttpResponse& response) {
  if (response.content_type == "image/png") {
    if (!response.body.starts_with("\x89PNG\r\n\x1a\n")) {
      Fail("a tile that is not a PNG", response.body.substr(0, 64));
    }
    return;
  }
  if (response.content_type == "application/vnd.quantized-mesh") {
    if (response.body.size() < 88 + 4 + 4 + 4 * 4) {
      Fail("a quantized-mesh tile shorter than an empty one",
           std::to_string(response.body.size()) + " bytes");
    }
    return;
  }
  google::protobuf::Struct tile_json;
  if (response.content_type != "application/json" ||
      !google::protobuf::util::JsonStringToMessage(response.body, &tile_json)
           .ok() ||
      !tile_json.fields().contains("tiles")) {
    Fail("a tile route answered neither a tile nor TileJSON", response.body);
  }
}

// An error message longer than this is a defect (issue 26: messages quote a
// short prefix of what they were sent, and the server cuts every status
// message to 1 KiB; inputs are up to 4 KiB).
constexpr size_t kMaxMessageBytes = 1024;

struct Fixture {
  std::shared_ptr<Engine> engine;
  std::unique_ptr<LocatorApp> app;
  std::unique_ptr<JsonApi> api;
  std::unique_ptr<OpenTopoDataApi> open_topo_data;
  std::unique_ptr<EdrApi> edr;
};

Fixture* MakeFixture() {
  auto* f = new Fixture;
  LocatorAppOptions options;
  options.max_batch_points = 64;
  options.max_profile_crossings = 20000;
  options.max_grid_cells = 4096;
  options.datasets = {DatasetConfig{.spec = "fixed"},
                      DatasetConfig{"other", "fixed", true},
                      DatasetConfig{"utm", "fixed", true}};
  f->app = std::make_unique<LocatorApp>(options);
  Dataset dataset = GenerateUniform(200, 3);
  for (const Point2& p : dataset.points) dataset.values.push_back(p.x - p.y);
  StatusOr<std::unique_ptr<Engine>> engine =
      Engine::Create(dataset, EngineOptions());
  if (!engine.ok()) Fail("cannot build the engine", "");
  // The same points 10 km across around 15°E 49.65°N, in UTM zone 33N.
  for (Point2& p : dataset.points) {
    p = {495000 + 10000 * p.x, 5495000 + 10000 * p.y};
  }
  gis::GuardedProjContext& ctx = gis::ThreadProjContext();
  const StatusOr<gis::PjPtr> crs = gis::CreateCrs(ctx, "EPSG:32633");
  if (!crs.ok()) Fail("no EPSG:32633", "");
  dataset.crs = proj_as_wkt(ctx.get(), crs->get(), PJ_WKT2_2019, nullptr);
  StatusOr<std::unique_ptr<Engine>> utm =
      Engine::Create(dataset, EngineOptions());
  if (!utm.ok()) Fail("cannot build the utm engine", "");
  f->engine = *std::move(engine);
  const auto& slots = f->app->datasets().slots();
  slots[0]->Publish({.engine = f->engine});
  slots[1]->Publish({.engine = f->engine});
  slots[2]->Publish({.engine = std::shared_ptr<Engine>(*std::move(utm))});
  f->api = std::make_unique<JsonApi>(f->app.get());
  f->open_topo_data =
      std::make_unique<OpenTopoDataApi>(f->app.get(), f->api.get());
  f->edr = std::make_unique<EdrApi>(f->app.get(), f->api.get());
  return f;
}

// Sends `request` to `api` and waits for the answer.
template <typename Api>
HttpResponse Call(Api& api, HttpRequest request) {
  std::promise<HttpResponse> answered;
  api.Handle(std::move(request), [&answered](HttpResponse response) {
    answered.set_value(std::move(response));
  });
  return answered.get_future().get();
}

template <typename Message>
Message ParseAnswer(const HttpResponse& response) {
  Message message;
  if (!google::protobuf::util::JsonStringToMessage(response.body, &message)
           .ok()) {
    Fail("the answer does not parse as " + message.GetTypeName(),
         response.body);
  }
  return message;
}

// Checks an error answer; returns its gRPC code.
int CheckError(const HttpResponse& response) {
  const auto error = ParseAnswer<google::protobuf::Struct>(response);
  const auto& fields = error.fields();
  if (fields.size() != 3 || fields.count("code") != 1 ||
      fields.count("status") != 1 || fields.count("message") != 1) {
    Fail("an error is not {code, status, message}", response.body);
  }
  const int code = static_cast<int>(fields.at("code").number_value());
  // INTERNAL and UNKNOWN (2, which no Status maps to) are the server's own.
  constexpr int kUnknown = 2;
  if (code == CanonicalCode(Status::Code::kInternal) || code == kUnknown) {
    Fail("an error that is not the caller's", response.body);
  }
  const std::string& message = fields.at("message").string_value();
  if (message.empty() || message.size() > kMaxMessageBytes) {
    Fail("an empty or long message", response.body.substr(0, 2000));
  }
  if (response.status != 405 &&
      response.status != HttpStatusForCanonicalCode(code)) {
    Fail("HTTP status " + std::to_string(response.status) + " for code " +
             std::to_string(code),
         response.body);
  }
  return code;
}

// Checks an Open Topo Data answer: OK with a result per location, or an
// error of its shape that is the caller's, with a short message.
void CheckOpenTopoDataAnswer(HttpResponse response) {
  // nodata_value=nan writes NaN, as Open Topo Data does: not JSON.
  for (size_t at = response.body.find("\"elevation\":NaN");
       at != std::string::npos;
       at = response.body.find("\"elevation\":NaN", at)) {
    response.body.replace(at + 12, 3, "null");
  }
  const auto answer = ParseAnswer<google::protobuf::Struct>(response);
  const auto& fields = answer.fields();
  const auto status = fields.find("status");
  if (status == fields.end()) Fail("no status", response.body);
  if (response.status == 200) {
    if (status->second.string_value() != "OK" || !fields.contains("results")) {
      Fail("a 200 that is not OK with results", response.body);
    }
    return;
  }
  const auto error = fields.find("error");
  if (fields.size() != 2 || error == fields.end() ||
      error->second.string_value().empty() ||
      error->second.string_value().size() > kMaxMessageBytes) {
    Fail("an error is not {error, status} with a short message",
         response.body.substr(0, 2000));
  }
  // Every fault is the caller's: Open Topo Data's client errors are 400
  // (404 for a path without a dataset, 405 for a method).
  if (status->second.string_value() != "INVALID_REQUEST" ||
      (response.status != 400 && response.status != 404 &&
       response.status != 405)) {
    Fail("an Open Topo Data error that is not the caller's", response.body);
  }
}

// Checks an EDR answer: a JSON document of its content type, or an
// ApiError.
void CheckEdrAnswer(const HttpResponse& response) {
  if (response.status != 200) {
    CheckError(response);
    return;
  }
  if (response.content_type != "application/prs.coverage+json" &&
      response.content_type != "application/geo+json" &&
      response.content_type != "application/json") {
    Fail("an EDR answer of type " + response.content_type, response.body);
  }
  ParseAnswer<google::protobuf::Struct>(response);
}

void CheckLocate(const Fixture& f, std::string_view body,
                 const HttpResponse& response) {
  v1::LocateRequest request;
  const bool parses =
      google::protobuf::util::JsonStringToMessage(
          body.empty() ? std::string_view("{}") : body, &request)
          .ok();
  const bool valid =
      parses && request.has_point() && std::isfinite(request.point().x()) &&
      std::isfinite(request.point().y()) &&
      (request.dataset().empty() || request.dataset() == "default") &&
      request.crs().empty();
  if (!valid) {
    // A CRS on a dataset without one, like every other fault, is the
    // caller's.
    if (response.status != 400 || CheckError(response) != 3) {
      Fail("a bad :locate body is not 400 INVALID_ARGUMENT", response.body);
    }
    return;
  }
  if (response.status != 200) {
    Fail(":locate of a valid body failed", response.body);
  }
  const auto answer = ParseAnswer<v1::LocateResponse>(response);
  LocateResult expected;
  if (!f.engine->Locate({request.point().x(), request.point().y()}, &expected)
           .ok()) {
    Fail("the engine refused a point the API located", response.body);
  }
  // On an edge or a vertex either incident triangle is right, and which
  // one a walk reports depends on where it started.
  const bool in_a_face = expected.type == LocationType::kFace;
  if (in_a_face && (answer.type() != v1::LOCATION_TYPE_FACE ||
                    answer.triangle_id() != expected.triangle_id)) {
    Fail(":locate answered another triangle than the engine", response.body);
  }
}

// A profile's breakpoints in order along the line, its crossings counted.
void CheckProfile(const v1::ProfileResponse& profile) {
  double last = 0;
  uint64_t crossings = 0;
  for (const v1::ProfilePoint& p : profile.breakpoints()) {
    if (p.distance() < last || p.distance() > profile.length()) {
      Fail(":profile breakpoints out of order", p.ShortDebugString());
    }
    last = p.distance();
    crossings += p.kind() != v1::PROFILE_POINT_KIND_LINE_VERTEX;
  }
  if (crossings != profile.crossings()) {
    Fail(":profile miscounted its crossings", profile.ShortDebugString());
  }
}

void FuzzOneInput(const uint8_t* data, size_t size) {
  static Fixture* fixture = MakeFixture();
  if (size == 0) return;
  const size_t route_index = data[0] % std::size(kRoutes);
  const Route& route = kRoutes[route_index];
  const std::string body(reinterpret_cast<const char*>(data + 1), size - 1);
  HttpRequest request;
  request.method = route.method;
  request.path = route.path;
  request.body = body;
  request.headers = {{"content-type", "application/json"}};
  if (IsOpenTopoDataRoute(route) || IsEdrRoute(route)) {
    if (request.method == "GET") {
      // The input is the query, or for EDR's collections the rest of the
      // path and the query.
      const size_t query = body.find('?');
      const bool in_path = std::string_view(route.path).ends_with("/");
      if (in_path) request.path += body.substr(0, query);
      request.query = !in_path                     ? body
                      : query == std::string::npos ? ""
                                                   : body.substr(query + 1);
      request.body.clear();
      request.headers.clear();
    }
    if (IsOpenTopoDataRoute(route)) {
      CheckOpenTopoDataAnswer(Call(*fixture->open_topo_data, request));
    } else {
      CheckEdrAnswer(Call(*fixture->edr, request));
    }
    return;
  }
  if (IsTileRoute(route)) {
    // The input goes into the path and the query, as the server hands
    // them over (split at the first '?').
    const size_t query = body.find('?');
    request.path += body.substr(0, query);
    request.query = query == std::string::npos ? "" : body.substr(query + 1);
    request.body.clear();
    request.headers.clear();
    const HttpResponse response = Call(*fixture->api, request);
    if (response.status == 200) {
      CheckTileAnswer(response);
    } else {
      CheckError(response);
    }
    return;
  }
  const HttpResponse response = Call(*fixture->api, request);
  if (response.content_type != "application/json") {
    Fail("not JSON: " + response.content_type, response.body);
  }
  if (response.status != 200) {
    CheckError(response);
  } else if (std::string_view(route.path).ends_with(":locateBatch")) {
    const auto answer = ParseAnswer<v1::LocateBatchResponse>(response);
    v1::LocateBatchRequest sent;
    if (!google::protobuf::util::JsonStringToMessage(
             body.empty() ? std::string_view("{}") : std::string_view(body),
             &sent)
             .ok() ||
        answer.types_size() != sent.xs_size()) {
      Fail(":locateBatch answered another number of points", response.body);
    }
  } else if (std::string_view(route.path).ends_with(":profile")) {
    CheckProfile(ParseAnswer<v1::ProfileResponse>(response));
  } else if (std::string_view(route.path).ends_with(":grid")) {
    const auto answer = ParseAnswer<v1::GridResponse>(response);
    const v1::GridHeader& header = answer.header();
    if (answer.rows() != header.height() ||
        answer.values_size() !=
            int64_t{header.width()} * int64_t{header.height()}) {
      Fail(":grid answered another number of cells", response.body);
    }
  } else if (std::string_view(route.path) == "/v1/datasets") {
    if (ParseAnswer<v1::ListDatasetsResponse>(response).datasets_size() != 3) {
      Fail("ListDatasets lost a dataset", response.body);
    }
  }
  // POST :locate of the default dataset.
  if (route_index == 0) CheckLocate(*fixture, body, response);
}

}  // namespace
}  // namespace locator

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  locator::FuzzOneInput(data, size);
  return 0;
}
