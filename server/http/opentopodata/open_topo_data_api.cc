#include "server/http/opentopodata/open_topo_data_api.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

// One call's answer as it is filled, dataset after dataset (Open Topo
// Data's multi-dataset requests): each point takes its value from the first
// dataset that has one there.
struct Lookup {
  // One per dataset named, in order.
  std::vector<LocatorApp::Admission> calls;
  OpenTopoDataQuery query;
  CallDeadline deadline;
  HttpReply reply;
  // Each result's location (x = longitude) and value (NaN: none yet).
  std::vector<Point2> where;
  std::vector<double> values;
  // The dataset each result names: the one that answered it, or the last.
  std::vector<size_t> answered_by;
};

// 200 with one result per point of `lookup`.
HttpResponse Answer(const Lookup& lookup) {
  JsonWriter json;
  json.Reserve(lookup.where.size() * 96 + 64);
  json.BeginObject().Key("results").BeginArray();
  for (size_t i = 0; i < lookup.where.size(); ++i) {
    json.BeginObject().Key("elevation");
    WriteElevation(lookup.values[i], lookup.query, &json);
    json.Key("location")
        .BeginObject()
        .Key("lat")
        .Number(lookup.where[i].y)
        .Key("lng")
        .Number(lookup.where[i].x)
        .EndObject()
        .Key("dataset")
        .String(lookup.calls[lookup.answered_by[i]].dataset->name())
        .EndObject();
  }
  json.EndArray().Key("status").String("OK").EndObject();
  return HttpResponse{.content_type = kJsonContentType,
                      .body = json.TakeText()};
}

// Asks dataset `k` of `lookup` for the points still without a value, then
// the next dataset, and answers after the last or once every point has a
// value.
void FillFrom(LocatorApp* app, std::shared_ptr<Lookup> lookup, size_t k) {
  std::vector<size_t> missing;
  for (size_t i = 0; i < lookup->values.size(); ++i) {
    if (std::isnan(lookup->values[i])) missing.push_back(i);
  }
  if (k == lookup->calls.size() || missing.empty()) {
    lookup->reply(Answer(*lookup));
    return;
  }
  ElevationQuery points{.points = {},
                        .crs = kLonLatCrs,
                        .interpolation = lookup->query.interpolation};
  for (const size_t i : missing) points.points.push_back(lookup->where[i]);
  LocateValues(app, lookup->calls[k], points, lookup->deadline,
               [app, lookup, k, missing = std::move(missing)](
                   StatusOr<std::vector<double>> values) {
                 if (!values.ok()) {
                   lookup->reply(OpenTopoDataError(values.status()));
                   return;
                 }
                 for (size_t j = 0; j < missing.size(); ++j) {
                   if (std::isnan((*values)[j])) continue;
                   lookup->values[missing[j]] = (*values)[j];
                   lookup->answered_by[missing[j]] = k;
                 }
                 FillFrom(app, lookup, k + 1);
               });
}

// Answers `lookup->query` (on a lane thread): a path's samples come from
// the first dataset's profile, and every point without a value there from
// the datasets after it.
void ServeOpenTopoData(LocatorApp* app, std::shared_ptr<Lookup> lookup) {
  const OpenTopoDataQuery& query = lookup->query;
  if (query.samples == 0) {
    lookup->where = query.points;
    lookup->values.assign(query.points.size(),
                          std::numeric_limits<double>::quiet_NaN());
    lookup->answered_by.assign(query.points.size(), lookup->calls.size() - 1);
    FillFrom(app, std::move(lookup), 0);
    return;
  }
  StatusOr<std::vector<LinePoint>> line =
      LineValues(*app, lookup->calls[0],
                 ElevationQuery{.points = query.points,
                                .crs = kLonLatCrs,
                                .interpolation = query.interpolation},
                 query.samples);
  if (!line.ok()) {
    lookup->reply(OpenTopoDataError(line.status()));
    return;
  }
  lookup->answered_by.assign(line->size(), lookup->calls.size() - 1);
  for (size_t i = 0; i < line->size(); ++i) {
    lookup->where.push_back((*line)[i].point);
    lookup->values.push_back((*line)[i].value);
    if (!std::isnan((*line)[i].value)) lookup->answered_by[i] = 0;
  }
  FillFrom(app, std::move(lookup), 1);
}

// The dataset names of a path's `{dataset}`, as Open Topo Data reads them:
// comma-separated, spaces and empty names dropped, none twice.
StatusOr<std::vector<std::string>> DatasetNames(std::string_view text) {
  std::vector<std::string> names;
  while (true) {
    const size_t comma = text.find(',');
    std::string_view name = text.substr(0, comma);
    while (name.starts_with(' ')) name.remove_prefix(1);
    while (name.ends_with(' ')) name.remove_suffix(1);
    if (!name.empty()) {
      if (std::find(names.begin(), names.end(), name) != names.end()) {
        return Status::InvalidArgument("Duplicate dataset names provided.");
      }
      if (names.size() == OpenTopoDataApi::kMaxDatasets) {
        return Status::InvalidArgument(
            "More than " + std::to_string(OpenTopoDataApi::kMaxDatasets) +
            " dataset names provided.");
      }
      names.emplace_back(name);
    }
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  if (names.empty()) {
    return Status::InvalidArgument("No valid dataset names provided.");
  }
  return names;
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
  StatusOr<std::vector<std::string>> names = DatasetNames(name);
  if (!names.ok()) {
    reply(OpenTopoDataError(names.status()));
    return;
  }
  // The deadline runs from the call's arrival: time queued counts.
  auto lookup = std::make_shared<Lookup>();
  lookup->deadline = app_->DefaultDeadline();
  for (const std::string& dataset : *names) {
    StatusOr<LocatorApp::Admission> call = app_->Admit(
        request.Header("authorization"), AccessPolicy::Scope::kData, dataset);
    if (!call.ok()) {
      reply(OpenTopoDataError(call.status()));
      return;
    }
    if (call->engine->dataset_info().crs.empty()) {
      reply(OpenTopoDataError(Status::InvalidArgument(
          "Dataset " + QuotedInput(dataset) +
          " has no coordinate reference system, so it cannot be queried by "
          "latitude and longitude; query it in its own coordinates with POST "
          "/v1/datasets/" +
          dataset + ":locateBatch")));
      return;
    }
    lookup->calls.push_back(*std::move(call));
  }
  // A large body is read in the expensive lane, as the JSON API reads its
  // bodies in its lanes, so that the HTTP server's threads never parse more
  // than kCheapBatchBodyBytes.
  if (request.body.size() > JsonApi::kCheapBatchBodyBytes) {
    const CallDeadline deadline = lookup->deadline;
    lanes_->RunCall(
        /*expensive=*/true, deadline, std::move(reply),
        [app = app_, lookup = std::move(lookup), request = std::move(request)](
            const Status& admitted, HttpReply reply) mutable {
          StatusOr<OpenTopoDataQuery> query =
              admitted.ok() ? QueryOf(request) : admitted;
          if (!query.ok()) {
            reply(OpenTopoDataError(query.status()));
            return;
          }
          lookup->query = *std::move(query);
          lookup->reply = std::move(reply);
          ServeOpenTopoData(app, std::move(lookup));
        });
    return;
  }
  StatusOr<OpenTopoDataQuery> query = QueryOf(request);
  if (!query.ok()) {
    reply(OpenTopoDataError(query.status()));
    return;
  }
  const bool expensive = IsExpensive(query->points.size(), query->samples > 0);
  lookup->query = *std::move(query);
  const CallDeadline deadline = lookup->deadline;
  lanes_->RunCall(expensive, deadline, std::move(reply),
                  [app = app_, lookup = std::move(lookup)](
                      const Status& admitted, HttpReply reply) mutable {
                    if (!admitted.ok()) {
                      reply(OpenTopoDataError(admitted));
                      return;
                    }
                    lookup->reply = std::move(reply);
                    ServeOpenTopoData(app, std::move(lookup));
                  });
}

}  // namespace locator
