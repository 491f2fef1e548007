#include "server/http/json/json_api.h"

#include <prometheus/gauge.h>

#include <chrono>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "common/input_text.h"
#include "common/proto_json.h"
#include "server/app/surface_convert.h"
#include "server/http/api_error.h"
#include "server/http/json/api_answers.h"
#include "server/http/json/grid_json.h"

namespace locator {
namespace {

constexpr std::string_view kDatasetsPath = "/v1/datasets";
// `registry`, or, when it is null, the one kept in `own`, made on the first
// call (a second one would destroy the families of the first).
prometheus::Registry& RegistryOr(prometheus::Registry* registry,
                                 std::shared_ptr<prometheus::Registry>* own) {
  if (registry != nullptr) return *registry;
  if (*own == nullptr) *own = std::make_shared<prometheus::Registry>();
  return **own;
}

}  // namespace

// One line per API method.
const JsonApi::DatasetRoute JsonApi::kDatasetRoutes[] = {
    {"locate", AccessPolicy::Scope::kData,
     &JsonApi::ServeUnary<v1::LocateRequest, v1::LocateResponse,
                          &LocatorApp::Locate>,
     std::numeric_limits<size_t>::max()},
    {"locateBatch", AccessPolicy::Scope::kData, &JsonApi::ServeLocateBatch,
     kCheapBatchBodyBytes},
    {"profile", AccessPolicy::Scope::kData,
     &JsonApi::ServeUnary<v1::ProfileRequest, v1::ProfileResponse,
                          &LocatorApp::Profile>,
     0},
    {"grid", AccessPolicy::Scope::kData, &JsonApi::ServeGrid, 0},
};

JsonApi::JsonApi(LocatorApp* app, JsonApiOptions options,
                 prometheus::Registry* registry)
    : app_(app),
      options_(options),
      running_(prometheus::BuildGauge()
                   .Name("locator_http_calls_running")
                   .Help("HTTP/JSON API calls running, by lane")
                   .Register(RegistryOr(registry, &own_registry_))),
      waiting_(prometheus::BuildGauge()
                   .Name("locator_http_calls_waiting")
                   .Help("HTTP/JSON API calls queued for a thread, by lane")
                   .Register(RegistryOr(registry, &own_registry_))),
      cheap_("cheap", kCheapThreads, options.max_waiting_calls, running_,
             waiting_),
      expensive_("expensive", kExpensiveThreads, options.max_waiting_calls,
                 running_, waiting_) {}

JsonApi::~JsonApi() { Shutdown(); }

void JsonApi::Shutdown() {
  pending_.Close();
  pending_.WaitUntilIdle(std::chrono::system_clock::time_point::max());
}

void JsonApi::Handle(HttpRequest request, HttpReply reply) {
  DrainGate::Ticket ticket = pending_.Enter();
  if (ticket == nullptr) {
    reply(ApiError(Status::Unavailable("server is shutting down")));
    return;
  }
  // The reply keeps the call counted until it has been answered.
  reply = [ticket = std::move(ticket), reply = std::move(reply)](
              HttpResponse response) { reply(std::move(response)); };
  const std::string_view path = request.path;
  if (path == kDatasetsPath) {
    ServeGet(request, std::nullopt, std::move(reply),
             [this](const LocatorApp::Admission&) {
               v1::ListDatasetsResponse response;
               app_->ListDatasets(&response);
               return JsonAnswer(response);
             });
    return;
  }
  const std::string_view prefix = "/v1/datasets/";
  if (!path.starts_with(prefix)) {
    reply(NoRoute(request));
    return;
  }
  // Dataset names have neither '/' nor ':', so a '/' after the name starts
  // the path of one of its resources (the tiles, the Cesium terrain).
  if (const size_t slash = path.find('/', prefix.size());
      slash != std::string_view::npos) {
    std::string name(path.substr(prefix.size(), slash - prefix.size()));
    std::string rest(path.substr(slash));
    if (rest.starts_with(kQuantizedMeshPrefix)) {
      rest.erase(0, kQuantizedMeshPrefix.size());
      ServeQuantizedMesh(std::move(request), std::move(name), std::move(rest),
                         std::move(reply));
      return;
    }
    ServeTiles(std::move(request), std::move(name), std::move(rest),
               std::move(reply));
    return;
  }
  const size_t colon = path.rfind(':');
  if (colon == std::string_view::npos || colon < prefix.size()) {
    reply(NoRoute(request));
    return;
  }
  std::string name(path.substr(prefix.size(), colon - prefix.size()));
  std::string method(path.substr(colon + 1));
  if (method == "topology") {
    ServeGet(request, name, std::move(reply),
             [this](const LocatorApp::Admission& call) {
               v1::GetTopologyResponse response;
               app_->GetTopology(call, &response);
               return JsonAnswer(response);
             });
    return;
  }
  ServeDatasetMethod(std::move(request), std::move(name), std::move(method),
                     std::move(reply));
}

void JsonApi::ServeGet(
    const HttpRequest& request, std::optional<std::string_view> dataset,
    HttpReply reply,
    const std::function<HttpResponse(const LocatorApp::Admission&)>& answer) {
  if (request.method != "GET") {
    reply(MethodNotAllowed(request, "GET"));
    return;
  }
  // Held until the answer is made: the call counts as in flight for a drain.
  const StatusOr<LocatorApp::Admission> call = app_->Admit(
      request.Header("authorization"), AccessPolicy::Scope::kData, dataset);
  if (!call.ok()) {
    reply(ApiError(call.status()));
    return;
  }
  reply(answer(*call));
}

void JsonApi::ServeDatasetMethod(HttpRequest request, std::string name,
                                 std::string method, HttpReply reply) {
  for (const DatasetRoute& route : kDatasetRoutes) {
    if (route.method != method) continue;
    if (request.method != "POST") {
      reply(MethodNotAllowed(request, "POST"));
      return;
    }
    // The deadline runs from the call's arrival: time queued counts.
    const CallDeadline deadline = app_->DefaultDeadline();
    StatusOr<LocatorApp::Admission> call =
        app_->Admit(request.Header("authorization"), route.scope, name);
    if (!call.ok()) {
      reply(ApiError(call.status()));
      return;
    }
    ApiLane& lane =
        request.body.size() <= route.cheap_up_to_bytes ? cheap_ : expensive_;
    RunInLane(lane, deadline, std::move(reply),
              [this, serve = route.serve, deadline, call = *std::move(call),
               request = std::move(request)](HttpReply reply) mutable {
                (this->*serve)(std::move(call), deadline, request,
                               std::move(reply));
              });
    return;
  }
  reply(NoRoute(request));
}

void JsonApi::RunCall(bool expensive, const CallDeadline& deadline,
                      HttpReply reply, LaneCall run) {
  DrainGate::Ticket ticket = pending_.Enter();
  if (ticket == nullptr) {
    run(Status::Unavailable("server is shutting down"), std::move(reply));
    return;
  }
  reply = [ticket = std::move(ticket), reply = std::move(reply)](
              HttpResponse response) { reply(std::move(response)); };
  SubmitToLane(expensive ? expensive_ : cheap_, deadline, std::move(reply),
               std::move(run));
}

void JsonApi::RunInLane(ApiLane& lane, const CallDeadline& deadline,
                        HttpReply reply,
                        std::function<void(HttpReply reply)> serve) {
  SubmitToLane(
      lane, deadline, std::move(reply),
      [serve = std::move(serve)](const Status& admitted, HttpReply reply) {
        if (!admitted.ok()) {
          reply(admitted.code() == Status::Code::kUnavailable
                    ? BusyError(admitted.message())
                    : ApiError(admitted));
          return;
        }
        serve(std::move(reply));
      });
}

void JsonApi::SubmitToLane(ApiLane& lane, const CallDeadline& deadline,
                           HttpReply reply, LaneCall run) {
  lane.Submit([&lane, deadline, reply = std::move(reply),
               run = std::move(run)](bool admitted) mutable {
    if (!admitted) {
      run(Status::Unavailable("the " + lane.name() + " lane of this server's " +
                              "HTTP API has " +
                              std::to_string(lane.max_waiting()) +
                              " calls waiting, its limit "
                              "(--http-max-waiting-calls); retry"),
          std::move(reply));
      return;
    }
    if (deadline.Passed()) {
      run(deadline.ExceededStatus("waiting for a thread"), std::move(reply));
      return;
    }
    run(Status::OK(), std::move(reply));
  });
}

template <typename Request, typename Response, auto run>
void JsonApi::ServeUnary(LocatorApp::Admission call,
                         const CallDeadline& /*deadline*/,
                         const HttpRequest& request, HttpReply reply) {
  Request parsed;
  if (Status bad = ParseBody(request, call.dataset->name(), &parsed);
      !bad.ok()) {
    reply(ApiError(bad));
    return;
  }
  Response response;
  const Status status = (app_->*run)(call, parsed, &response);
  reply(status.ok() ? JsonAnswer(response) : ApiError(status));
}

void JsonApi::ServeLocateBatch(LocatorApp::Admission call,
                               const CallDeadline& deadline,
                               const HttpRequest& request, HttpReply reply) {
  // Both live until the batch has finished, which may be on another thread.
  struct Batch {
    v1::LocateBatchRequest request;
    v1::LocateBatchResponse response;
  };
  auto batch = std::make_shared<Batch>();
  if (Status bad = ParseBody(request, call.dataset->name(), &batch->request);
      !bad.ok()) {
    reply(ApiError(bad));
    return;
  }
  app_->LocateBatch(
      std::move(call), batch->request,
      BatchLocator::CallControl{
          .deadline = deadline,
          .cancelled = nullptr,
          .finish =
              [batch, reply = std::move(reply)](const Status& status) {
                reply(status.ok() ? JsonAnswer(batch->response)
                                  : ApiError(status));
              }},
      &batch->response);
}

void JsonApi::ServeGrid(LocatorApp::Admission call,
                        const CallDeadline& deadline,
                        const HttpRequest& request, HttpReply reply) {
  v1::GridRequest parsed;
  if (Status bad = ParseBody(request, call.dataset->name(), &parsed);
      !bad.ok()) {
    reply(ApiError(bad));
    return;
  }
  // The HTTP limit is checked first, so that its error names its flag.
  RasterSpec shape;
  if (const Status over =
          FromGridRequest(parsed, options_.max_grid_cells, &shape);
      over.code() == Status::Code::kResourceExhausted) {
    reply(ApiError(over.WithMessage(
        over.message() +
        " (--http-max-grid-cells: an HTTP :grid answers in one JSON text; "
        "the gRPC Grid streams up to --max-grid-cells)")));
    return;
  }
  StatusOr<RasterSpec> spec = app_->GridSpec(call, parsed);
  if (!spec.ok()) {
    reply(ApiError(spec.status()));
    return;
  }
  std::string json;
  const Status status = GridJson(*call.engine, *spec, deadline, &json);
  reply(status.ok() ? HttpResponse{.content_type = kJsonContentType,
                                   .body = std::move(json)}
                    : ApiError(status));
}

}  // namespace locator
