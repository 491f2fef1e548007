#include "server/http/opentopodata/open_topo_data_api.h"

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common/input_text.h"
#include "common/json_writer.h"
#include "server/http/api_error.h"
#include "server/http/elevation/elevation_calls.h"
#include "server/http/elevation/request_fields.h"
#include "server/http/opentopodata/open_topo_data_query.h"

namespace locator {
namespace {

constexpr std::string_view kVersionPrefix = "/opentopodata/v1/";

// Open Topo Data's answer to a path without a dataset.
HttpResponse NoDataset() {
  HttpResponse answer = OpenTopoDataError(Status::InvalidArgument(
      "No dataset name provided. Try a url like "
      "'/opentopodata/v1/DATASET?locations=-10,120' to get started; "
      "GET /v1/datasets lists this server's datasets."));
  answer.status = 404;
  return answer;
}

// The answer's elevation at a point without a value.
void WriteElevation(double value, const OpenTopoDataQuery& query,
                    JsonWriter* json) {
  if (!std::isnan(value)) {
    json->Number(value);
  } else if (const int64_t* integer = std::get_if<int64_t>(&query.nodata)) {
    json->Raw(std::to_string(*integer));
  } else if (std::get<OpenTopoDataQuery::NoData>(query.nodata) ==
             OpenTopoDataQuery::NoData::kNan) {
    // Not JSON, but what Open Topo Data (Python's json) writes for it.
    json->Raw("NaN");
  } else {
    json->Null();
  }
}

// 200 with one result per point: `where` (x = longitude) and its value.
HttpResponse Answer(const std::vector<Point2>& where,
                    const std::vector<double>& values,
                    const OpenTopoDataQuery& query, std::string_view dataset) {
  JsonWriter json;
  json.Reserve(where.size() * 96 + 64);
  json.BeginObject().Key("results").BeginArray();
  for (size_t i = 0; i < where.size(); ++i) {
    json.BeginObject().Key("elevation");
    WriteElevation(values[i], query, &json);
    json.Key("location")
        .BeginObject()
        .Key("lat")
        .Number(where[i].y)
        .Key("lng")
        .Number(where[i].x)
        .EndObject()
        .Key("dataset")
        .String(dataset)
        .EndObject();
  }
  json.EndArray().Key("status").String("OK").EndObject();
  return HttpResponse{.content_type = kJsonContentType,
                      .body = json.TakeText()};
}

// Answers `query` on the admitted `call` (on a lane thread).
void ServeOpenTopoData(LocatorApp* app, LocatorApp::Admission call,
                       const OpenTopoDataQuery& query,
                       const CallDeadline& deadline, HttpReply reply) {
  const ElevationQuery points{.points = query.points,
                              .crs = kLonLatCrs,
                              .interpolation = query.interpolation};
  const std::string dataset = call.dataset->name();
  if (query.samples > 0) {
    StatusOr<std::vector<LinePoint>> line =
        LineValues(*app, call, points, query.samples);
    if (!line.ok()) {
      reply(OpenTopoDataError(line.status()));
      return;
    }
    std::vector<Point2> where;
    std::vector<double> values;
    for (const LinePoint& p : *line) {
      where.push_back(p.point);
      values.push_back(p.value);
    }
    reply(Answer(where, values, query, dataset));
    return;
  }
  LocateValues(
      app, std::move(call), points, deadline,
      [query, dataset,
       reply = std::move(reply)](StatusOr<std::vector<double>> values) {
        reply(values.ok() ? Answer(query.points, *values, query, dataset)
                          : OpenTopoDataError(values.status()));
      });
}

// The query `request` asks for.
StatusOr<OpenTopoDataQuery> QueryOf(const HttpRequest& request) {
  StatusOr<RequestFields> fields = RequestFields::Of(request);
  if (!fields.ok()) return fields.status();
  return ParseOpenTopoDataQuery(*fields);
}

}  // namespace

void OpenTopoDataApi::Handle(HttpRequest request, HttpReply reply) {
  const std::string_view path = request.path;
  if (!path.starts_with(kVersionPrefix) ||
      path.size() == kVersionPrefix.size()) {
    reply(NoDataset());
    return;
  }
  const std::string_view name = path.substr(kVersionPrefix.size());
  if (name.find('/') != std::string_view::npos) {
    HttpResponse answer = OpenTopoDataError(Status::NotFound(
        "no such path: " + QuotedInput(path) +
        "; Open Topo Data's path is /opentopodata/v1/{dataset}"));
    answer.status = 404;
    reply(std::move(answer));
    return;
  }
  if (request.method != "GET" && request.method != "POST") {
    HttpResponse answer = OpenTopoDataError(Status::InvalidArgument(
        request.method.substr(0, kQuotedInputBytes) +
        " is not allowed: Open Topo Data answers GET and POST"));
    answer.status = 405;
    answer.headers.emplace_back("Allow", "GET, HEAD, POST");
    reply(std::move(answer));
    return;
  }
  // The deadline runs from the call's arrival: time queued counts.
  const CallDeadline deadline = app_->DefaultDeadline();
  StatusOr<LocatorApp::Admission> call = app_->Admit(
      request.Header("authorization"), AccessPolicy::Scope::kData, name);
  if (!call.ok()) {
    reply(OpenTopoDataError(call.status()));
    return;
  }
  if (call->engine->dataset_info().crs.empty()) {
    reply(OpenTopoDataError(Status::InvalidArgument(
        "Dataset " + QuotedInput(call->dataset->name()) +
        " has no coordinate reference system, so it cannot be queried by "
        "latitude and longitude; query it in its own coordinates with POST "
        "/v1/datasets/" +
        call->dataset->name() + ":locateBatch")));
    return;
  }
  // A large body is read in the expensive lane, as the JSON API reads its
  // bodies in its lanes, so that the HTTP server's threads never parse more
  // than kCheapBatchBodyBytes.
  if (request.body.size() > JsonApi::kCheapBatchBodyBytes) {
    lanes_->RunCall(
        /*expensive=*/true, deadline, std::move(reply),
        [app = app_, call = *std::move(call), request = std::move(request),
         deadline](const Status& admitted, HttpReply reply) mutable {
          StatusOr<OpenTopoDataQuery> query =
              admitted.ok() ? QueryOf(request) : admitted;
          if (!query.ok()) {
            reply(OpenTopoDataError(query.status()));
            return;
          }
          ServeOpenTopoData(app, std::move(call), *query, deadline,
                            std::move(reply));
        });
    return;
  }
  StatusOr<OpenTopoDataQuery> query = QueryOf(request);
  if (!query.ok()) {
    reply(OpenTopoDataError(query.status()));
    return;
  }
  const bool expensive = IsExpensive(query->points.size(), query->samples > 0);
  lanes_->RunCall(
      expensive, deadline, std::move(reply),
      [app = app_, call = *std::move(call), query = *std::move(query),
       deadline](const Status& admitted, HttpReply reply) mutable {
        if (!admitted.ok()) {
          reply(OpenTopoDataError(admitted));
          return;
        }
        ServeOpenTopoData(app, std::move(call), query, deadline,
                          std::move(reply));
      });
}

}  // namespace locator
