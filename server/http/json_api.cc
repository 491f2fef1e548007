#include "server/http/json_api.h"

#include <google/protobuf/util/json_util.h>

#include <chrono>
#include <memory>
#include <string>
#include <utility>

#include "common/proto_json.h"
#include "server/http/api_error.h"

namespace locator {
namespace {

constexpr std::string_view kDatasetsPath = "/v1/datasets";

grpc::Status InvalidArgument(const std::string& message) {
  return grpc::Status(grpc::StatusCode::INVALID_ARGUMENT, message);
}

HttpResponse JsonAnswer(const google::protobuf::Message& message) {
  return HttpResponse{.content_type = kJsonContentType,
                      .body = ProtoJson(message)};
}

HttpResponse NoRoute(const HttpRequest& request) {
  return ApiError(
      grpc::Status(grpc::StatusCode::NOT_FOUND,
                   "no API method " + request.method + " " + request.path +
                       " (GET /v1/datasets, POST /v1/datasets/{name}:locate, "
                       ":locateBatch, :profile or :grid)"));
}

HttpResponse MethodNotAllowed(const HttpRequest& request,
                              std::string_view allowed) {
  HttpResponse response =
      ApiError(grpc::Status(grpc::StatusCode::UNIMPLEMENTED,
                            request.method + " is not allowed on " +
                                request.path + "; use " + std::string(allowed)),
               405);
  response.headers.emplace_back("Allow", std::string(allowed));
  return response;
}

// Parses the body of a request for dataset `dataset` (the path's) into
// *out, whose `dataset` field it sets. INVALID_ARGUMENT naming the parse
// error, or a body `dataset` other than the path's.
template <typename Request>
grpc::Status ParseBody(const HttpRequest& request, std::string_view dataset,
                       Request* out) {
  google::protobuf::util::JsonParseOptions options;
  options.ignore_unknown_fields = false;
  const std::string_view body =
      request.body.empty() ? std::string_view("{}") : request.body;
  if (const auto parsed =
          google::protobuf::util::JsonStringToMessage(body, out, options);
      !parsed.ok()) {
    // Protobuf adds a picture of the position on further lines.
    const std::string_view error(parsed.message().data(),
                                 parsed.message().size());
    return InvalidArgument(
        "the body is not a " + out->GetTypeName() +
        " in JSON: " + std::string(error.substr(0, error.find('\n'))));
  }
  if (!out->dataset().empty() && out->dataset() != dataset) {
    return InvalidArgument("the body names dataset '" + out->dataset() +
                           "' but the path names '" + std::string(dataset) +
                           "'");
  }
  out->set_dataset(std::string(dataset));
  return grpc::Status::OK;
}

}  // namespace

// One line per API method.
const JsonApi::DatasetRoute JsonApi::kDatasetRoutes[] = {
    {"locate", AccessPolicy::Scope::kData,
     &JsonApi::ServeUnary<v1::LocateRequest, v1::LocateResponse,
                          &LocatorService::RunLocate>},
    {"locateBatch", AccessPolicy::Scope::kData, &JsonApi::ServeLocateBatch},
    {"profile", AccessPolicy::Scope::kData,
     &JsonApi::ServeUnary<v1::ProfileRequest, v1::ProfileResponse,
                          &LocatorService::RunProfile>},
    {"grid", AccessPolicy::Scope::kData,
     &JsonApi::ServeUnary<v1::GridRequest, v1::GridResponse,
                          &LocatorService::RunGrid>},
};

JsonApi::JsonApi(LocatorService* service)
    : service_(service), workers_(kThreads) {}

JsonApi::~JsonApi() { Shutdown(); }

void JsonApi::Shutdown() {
  pending_.Close();
  pending_.WaitUntilIdle(std::chrono::system_clock::time_point::max());
}

void JsonApi::Handle(HttpRequest request, HttpReply reply) {
  DrainGate::Ticket ticket = pending_.Enter();
  if (ticket == nullptr) {
    reply(ApiError(grpc::Status(grpc::StatusCode::UNAVAILABLE,
                                "server is shutting down")));
    return;
  }
  // The reply keeps the call counted until it has been answered.
  reply = [ticket = std::move(ticket), reply = std::move(reply)](
              HttpResponse response) { reply(std::move(response)); };
  const std::string_view path = request.path;
  if (path == kDatasetsPath) {
    ServeListDatasets(request, std::move(reply));
    return;
  }
  const std::string_view prefix = "/v1/datasets/";
  const size_t colon = path.rfind(':');
  if (!path.starts_with(prefix) || colon == std::string_view::npos ||
      colon < prefix.size()) {
    reply(NoRoute(request));
    return;
  }
  std::string name(path.substr(prefix.size(), colon - prefix.size()));
  std::string method(path.substr(colon + 1));
  ServeDatasetMethod(std::move(request), std::move(name), std::move(method),
                     std::move(reply));
}

void JsonApi::ServeListDatasets(const HttpRequest& request, HttpReply reply) {
  if (request.method != "GET") {
    reply(MethodNotAllowed(request, "GET"));
    return;
  }
  LocatorService::Admission call;
  if (grpc::Status refused =
          service_->Admit(request.Header("authorization"),
                          AccessPolicy::Scope::kData, std::nullopt, &call);
      !refused.ok()) {
    reply(ApiError(refused));
    return;
  }
  v1::ListDatasetsResponse response;
  service_->RunListDatasets(&response);
  reply(JsonAnswer(response));
}

void JsonApi::ServeDatasetMethod(HttpRequest request, std::string name,
                                 std::string method, HttpReply reply) {
  for (const DatasetRoute& route : kDatasetRoutes) {
    if (route.method != method) continue;
    if (request.method != "POST") {
      reply(MethodNotAllowed(request, "POST"));
      return;
    }
    LocatorService::Admission call;
    if (grpc::Status refused = service_->Admit(request.Header("authorization"),
                                               route.scope, name, &call);
        !refused.ok()) {
      reply(ApiError(refused));
      return;
    }
    workers_.Submit([this, serve = route.serve, call = std::move(call),
                     request = std::move(request),
                     reply = std::move(reply)]() mutable {
      (this->*serve)(std::move(call), request, std::move(reply));
    });
    return;
  }
  reply(NoRoute(request));
}

template <typename Request, typename Response, auto run>
void JsonApi::ServeUnary(LocatorService::Admission call,
                         const HttpRequest& request, HttpReply reply) {
  Request parsed;
  if (grpc::Status bad = ParseBody(request, call.dataset->name(), &parsed);
      !bad.ok()) {
    reply(ApiError(bad));
    return;
  }
  Response response;
  const grpc::Status status = (service_->*run)(call, parsed, &response);
  reply(status.ok() ? JsonAnswer(response) : ApiError(status));
}

void JsonApi::ServeLocateBatch(LocatorService::Admission call,
                               const HttpRequest& request, HttpReply reply) {
  // Both live until the batch has finished, which may be on another thread.
  struct Batch {
    v1::LocateBatchRequest request;
    v1::LocateBatchResponse response;
  };
  auto batch = std::make_shared<Batch>();
  if (grpc::Status bad =
          ParseBody(request, call.dataset->name(), &batch->request);
      !bad.ok()) {
    reply(ApiError(bad));
    return;
  }
  service_->RunLocateBatch(
      std::move(call), batch->request,
      BatchLocator::CallControl{
          .deadline = service_->DefaultDeadline(),
          .cancelled = nullptr,
          .finish =
              [batch, reply = std::move(reply)](const grpc::Status& status) {
                reply(status.ok() ? JsonAnswer(batch->response)
                                  : ApiError(status));
              }},
      &batch->response);
}

}  // namespace locator
