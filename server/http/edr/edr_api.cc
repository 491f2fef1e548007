#include "server/http/edr/edr_api.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/input_text.h"
#include "common/json_writer.h"
#include "common/status_macros.h"
#include "server/app/request_crs.h"
#include "server/http/api_error.h"
#include "server/http/edr/coverage_json.h"
#include "server/http/edr/edr_metadata.h"
#include "server/http/edr/edr_parameters.h"
#include "server/http/edr/wkt_coordinates.h"
#include "server/http/elevation/elevation_calls.h"
#include "server/http/json/api_answers.h"

namespace locator {
namespace {

constexpr std::string_view kCollectionsPath = "/edr/collections";
constexpr std::string_view kPosition = "position";
constexpr std::string_view kTrajectory = "trajectory";
// Points per side of the box sampled for its longitude/latitude extent: a
// projected box's edges are curves in longitude/latitude.
constexpr int kExtentPointsPerSide = 16;

HttpResponse EdrError(const Status& status) {
  return status.code() == Status::Code::kUnavailable
             ? BusyError(status.message())
             : ApiError(status);
}

HttpResponse JsonText(std::string body) {
  return HttpResponse{.content_type = kJsonContentType,
                      .body = std::move(body)};
}

HttpResponse NoEdrRoute(const HttpRequest& request) {
  return ApiError(Status::NotFound(
      "no EDR resource " + QuotedInput(request.path) +
      " (GET /edr/, /edr/conformance, /edr/collections, "
      "/edr/collections/{name}, /edr/collections/{name}/position or "
      "/trajectory)"));
}

// The admitted dataset's collection facts: its statistics as GetStats
// answers them, and its box in longitude/latitude where it has a CRS.
EdrCollectionFacts FactsOf(const LocatorApp& app,
                           const LocatorApp::Admission& call) {
  v1::GetStatsResponse stats;
  app.GetStats(call, &stats);
  EdrCollectionFacts facts{.stats = stats.dataset(), .lon_lat_box = {}};
  const v1::BoundingBox& box = facts.stats.bounding_box();
  if (!facts.stats.has_crs()) return facts;
  std::vector<Point2> outline;
  for (int i = 0; i <= kExtentPointsPerSide; ++i) {
    const double t = static_cast<double>(i) / kExtentPointsPerSide;
    const double x = box.min_x() + t * (box.max_x() - box.min_x());
    const double y = box.min_y() + t * (box.max_y() - box.min_y());
    outline.insert(outline.end(), {{x, box.min_y()},
                                   {x, box.max_y()},
                                   {box.min_x(), y},
                                   {box.max_x(), y}});
  }
  if (!PointsInRequestCrs(*call.engine, kLonLatCrs, outline).ok()) {
    return facts;
  }
  BoundingBox lon_lat;
  for (const Point2& p : outline) lon_lat.Extend(p);
  facts.lon_lat_box = lon_lat;
  return facts;
}

// A position or trajectory query, parsed.
struct EdrQuery {
  ElevationQuery points;
  CoveragePoints::Domain domain = CoveragePoints::Domain::kPoint;
  uint32_t samples = 0;
  EdrFormat format = EdrFormat::kCoverageJson;
  EdrCrs crs;
};

StatusOr<uint32_t> ParseTrajectorySamples(
    std::optional<std::string_view> text) {
  if (!text.has_value()) return 0u;
  uint32_t samples = 0;
  const auto [end, error] =
      std::from_chars(text->data(), text->data() + text->size(), samples);
  if (text->empty() || error != std::errc() ||
      end != text->data() + text->size() || samples < 2) {
    return Status::InvalidArgument(
        "samples: " + QuotedInput(*text) +
        " is not a whole number from 2 to 4294967295 (the line's first and "
        "last points are samples)");
  }
  return samples;
}

StatusOr<EdrQuery> ParseQuery(const RequestFields& fields,
                              std::string_view query,
                              const v1::DatasetStats& stats) {
  EdrQuery parsed;
  if (const std::optional<std::string_view> parameter =
          fields.Get("parameter-name");
      parameter.has_value() && *parameter != kElevationParameter) {
    return Status::InvalidArgument(
        "parameter-name: " + QuotedInput(*parameter) +
        " is not a parameter of this collection; "
        "its one parameter is elevation");
  }
  ASSIGN_OR_RETURN(parsed.format, ParseEdrFormat(fields.Get("f")));
  ASSIGN_OR_RETURN(parsed.crs,
                   ParseEdrCrs(fields.Get("crs"), OfferedCrs(stats)));
  const std::optional<std::string_view> coords = fields.Get("coords");
  if (!coords.has_value()) {
    return Status::InvalidArgument(
        "coords is required: " +
        std::string(query == kPosition ? "POINT(x y) or MULTIPOINT((x y),(x y))"
                                       : "LINESTRING(x y, x y, ...)"));
  }
  ASSIGN_OR_RETURN(WktCoordinates geometry,
                   ParseWktCoordinates(*coords, EdrApi::kMaxCoordsPoints));
  using Type = WktCoordinates::Type;
  if (query == kPosition) {
    if (geometry.type == Type::kLineString) {
      return Status::InvalidArgument(
          "coords: a position query takes a POINT or a MULTIPOINT; a "
          "LINESTRING is a trajectory query's");
    }
    parsed.domain = geometry.type == Type::kPoint
                        ? CoveragePoints::Domain::kPoint
                        : CoveragePoints::Domain::kMultiPoint;
    if (fields.Get("samples").has_value()) {
      return Status::InvalidArgument(
          "samples is a trajectory query's parameter, not a position's");
    }
  } else {
    if (geometry.type != Type::kLineString) {
      return Status::InvalidArgument(
          "coords: a trajectory query takes a LINESTRING");
    }
    parsed.domain = CoveragePoints::Domain::kTrajectory;
    ASSIGN_OR_RETURN(parsed.samples,
                     ParseTrajectorySamples(fields.Get("samples")));
  }
  if (parsed.crs.lon_lat) {
    for (size_t i = 0; i < geometry.points.size(); ++i) {
      const Point2& p = geometry.points[i];
      if (p.x < -180 || p.x > 180 || p.y < -90 || p.y > 90) {
        return Status::InvalidArgument(
            "coords: point " + std::to_string(i) + " " + PointText(p) +
            " is not a longitude in [-180, 180] and a latitude in [-90, 90] "
            "(" +
            parsed.crs.uri + " is longitude first)");
      }
    }
  }
  parsed.points = ElevationQuery{.points = std::move(geometry.points),
                                 .crs = parsed.crs.request_crs,
                                 .interpolation = v1::INTERPOLATION_LINEAR};
  return parsed;
}

// Runs `query` on the admitted `call` (on a lane thread).
void ServeEdrQuery(LocatorApp* app, LocatorApp::Admission call,
                   const EdrQuery& query, const CallDeadline& deadline,
                   HttpReply reply) {
  const auto answer = [query](CoveragePoints points) {
    return HttpResponse{
        .content_type = std::string(EdrContentType(query.format)),
        .body = CoverageText(points, query.crs, query.format)};
  };
  if (query.domain == CoveragePoints::Domain::kTrajectory) {
    StatusOr<std::vector<LinePoint>> line =
        LineValues(*app, call, query.points, query.samples);
    if (!line.ok()) {
      reply(EdrError(line.status()));
      return;
    }
    CoveragePoints points;
    points.domain = query.domain;
    for (const LinePoint& p : *line) {
      points.where.push_back(p.point);
      points.values.push_back(p.value);
      points.distances.push_back(p.distance);
    }
    reply(answer(std::move(points)));
    return;
  }
  LocateValues(app, std::move(call), query.points, deadline,
               [query, answer, reply = std::move(reply)](
                   StatusOr<std::vector<double>> values) {
                 if (!values.ok()) {
                   reply(EdrError(values.status()));
                   return;
                 }
                 reply(answer(CoveragePoints{.domain = query.domain,
                                             .where = query.points.points,
                                             .values = *std::move(values),
                                             .distances = {}}));
               });
}

}  // namespace

bool EdrApi::Serves(std::string_view path) {
  return path == kEdrPath ||
         (path.starts_with(kEdrPath) && path[kEdrPath.size()] == '/');
}

void EdrApi::Handle(HttpRequest request, HttpReply reply) {
  if (request.method != "GET") {
    reply(MethodNotAllowed(request, "GET"));
    return;
  }
  std::string_view path = request.path;
  if (path == kEdrPath || path == "/edr/") {
    reply(JsonText(EdrLandingPage()));
    return;
  }
  if (path == "/edr/conformance") {
    reply(JsonText(EdrConformance()));
    return;
  }
  if (path == kCollectionsPath || path == "/edr/collections/") {
    ServeCollections(request, std::move(reply));
    return;
  }
  if (!path.starts_with(std::string(kCollectionsPath) + "/")) {
    reply(NoEdrRoute(request));
    return;
  }
  path.remove_prefix(kCollectionsPath.size() + 1);
  const size_t slash = path.find('/');
  std::string name(path.substr(0, slash));
  std::string query;
  if (slash != std::string_view::npos) {
    query = std::string(path.substr(slash + 1));
    if (query != kPosition && query != kTrajectory) {
      reply(NoEdrRoute(request));
      return;
    }
  }
  ServeCollection(request, std::move(name), std::move(query), std::move(reply));
}

std::optional<LocatorApp::Admission> EdrApi::Admit(
    const HttpRequest& request, std::optional<std::string_view> dataset,
    HttpReply& reply) const {
  StatusOr<LocatorApp::Admission> call = app_->Admit(
      request.Header("authorization"), AccessPolicy::Scope::kData, dataset);
  if (!call.ok()) {
    reply(EdrError(call.status()));
    return std::nullopt;
  }
  return *std::move(call);
}

void EdrApi::ServeDocument(const HttpRequest& request,
                           std::optional<std::string_view> dataset,
                           WriteDocument write, HttpReply reply) {
  // The deadline runs from the call's arrival: time queued counts.
  const CallDeadline deadline = app_->DefaultDeadline();
  std::optional<LocatorApp::Admission> call = Admit(request, dataset, reply);
  if (!call.has_value()) return;
  lanes_->RunCall(
      /*expensive=*/false, deadline, std::move(reply),
      // The admission keeps the call counted for a drain until it answers.
      [app = app_, call = *std::move(call), write = std::move(write)](
          const Status& admitted, HttpReply reply) {
        if (!admitted.ok()) {
          reply(EdrError(admitted));
          return;
        }
        JsonWriter json;
        write(*app, call, &json);
        reply(JsonText(json.TakeText()));
      });
}

void EdrApi::ServeCollections(const HttpRequest& request, HttpReply reply) {
  ServeDocument(
      request, std::nullopt,
      [](const LocatorApp& app, const LocatorApp::Admission&,
         JsonWriter* json) {
        json->BeginObject().Key("links").BeginArray().BeginObject();
        json->Key("href").String(kCollectionsPath).Key("rel").String("self");
        json->EndObject().EndArray().Key("collections").BeginArray();
        // Datasets still loading have no collection yet.
        for (const auto& slot : app.datasets().slots()) {
          const StatusOr<LocatorApp::Admission> dataset =
              app.Resolve(slot->name());
          if (dataset.ok()) WriteEdrCollection(FactsOf(app, *dataset), json);
        }
        json->EndArray().EndObject();
      },
      std::move(reply));
}

void EdrApi::ServeCollection(const HttpRequest& request, std::string name,
                             std::string query, HttpReply reply) {
  if (query.empty()) {
    ServeDocument(
        request, name,
        [](const LocatorApp& app, const LocatorApp::Admission& call,
           JsonWriter* json) { WriteEdrCollection(FactsOf(app, call), json); },
        std::move(reply));
    return;
  }
  // The deadline runs from the call's arrival: time queued counts.
  const CallDeadline deadline = app_->DefaultDeadline();
  std::optional<LocatorApp::Admission> call = Admit(request, name, reply);
  if (!call.has_value()) return;
  StatusOr<RequestFields> fields = RequestFields::Of(request);
  if (!fields.ok()) {
    reply(EdrError(fields.status()));
    return;
  }
  v1::GetStatsResponse stats;
  app_->GetStats(*call, &stats);
  StatusOr<EdrQuery> parsed = ParseQuery(*fields, query, stats.dataset());
  if (!parsed.ok()) {
    reply(EdrError(parsed.status()));
    return;
  }
  const bool expensive =
      IsExpensive(parsed->points.points.size(),
                  parsed->domain == CoveragePoints::Domain::kTrajectory);
  lanes_->RunCall(
      expensive, deadline, std::move(reply),
      [app = app_, call = *std::move(call), parsed = *std::move(parsed),
       deadline](const Status& admitted, HttpReply reply) mutable {
        if (!admitted.ok()) {
          reply(EdrError(admitted));
          return;
        }
        ServeEdrQuery(app, std::move(call), parsed, deadline, std::move(reply));
      });
}

}  // namespace locator
