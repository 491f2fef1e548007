#include "server/route/router_http_api.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "common/input_text.h"
#include "server/http/api_error.h"
#include "server/http/json/api_answers.h"
#include "server/metrics/metrics_text.h"

namespace locator {
namespace {

constexpr std::string_view kPrefix = "/v1/datasets/";
constexpr std::chrono::seconds kLastResortDeadline{60};

HttpResponse NotRouted(const HttpRequest& request) {
  return ApiError(Status::NotFound(
      "the router has no route " +
      QuotedInput(request.method + " " + request.path) +
      " (POST /v1/datasets/{name}:locate, :locateBatch, :profile, :grid, "
      "GET /v1/datasets/{name}:topology, GET /metrics); terrain tiles and "
      "the elevation APIs are a shard's"));
}

// One HTTP call's request and response, alive until it is answered.
template <typename Request, typename Response>
struct Exchange {
  Request request;
  Response response;
};

}  // namespace

RouterHttpApi::RouterHttpApi(ShardRouter* router,
                             std::chrono::milliseconds deadline,
                             std::function<std::string()> metrics_text)
    : router_(router),
      deadline_(deadline.count() > 0
                    ? deadline
                    : std::chrono::milliseconds(kLastResortDeadline)),
      metrics_text_(std::move(metrics_text)) {}

void RouterHttpApi::Handle(HttpRequest request, HttpReply reply) {
  const std::string_view path = request.path;
  if (path == "/metrics") {
    reply(request.method == "GET"
              ? HttpResponse{200, kMetricsContentType, metrics_text_()}
              : MethodNotAllowed(request, "GET"));
    return;
  }
  const size_t colon = path.rfind(':');
  if (!path.starts_with(kPrefix) || colon == std::string_view::npos ||
      colon < kPrefix.size() ||
      path.find('/', kPrefix.size()) != std::string_view::npos) {
    reply(NotRouted(request));
    return;
  }
  const std::string name(path.substr(kPrefix.size(), colon - kPrefix.size()));
  const std::string_view method = path.substr(colon + 1);
  const bool post = method == "locate" || method == "locateBatch" ||
                    method == "profile" || method == "grid";
  if (!post && method != "topology") {
    reply(NotRouted(request));
    return;
  }
  if (request.method != (post ? "POST" : "GET")) {
    reply(MethodNotAllowed(request, post ? "POST" : "GET"));
    return;
  }
  std::optional<std::string> authorization;
  if (const auto header = request.Header("authorization")) {
    authorization = std::string(*header);
  }
  const auto deadline = std::chrono::system_clock::now() + deadline_;
  const auto call = [&](auto exchange) {
    return ShardRouter::Call{
        .authorization = authorization,
        .new_context =
            [this, deadline, authorization] {
              auto context = router_->topology().NewContext(
                  std::make_unique<grpc::ClientContext>());
              context->set_deadline(deadline);
              if (authorization) {
                context->AddMetadata("authorization", *authorization);
              }
              return context;
            },
        .finish =
            [exchange, reply](grpc::Status status) {
              reply(status.ok() ? JsonAnswer(exchange->response)
                                : ApiError(status.error_code(),
                                           status.error_message()));
            }};
  };
  // A POST's body is the request, for the dataset the path names.
  const auto forward = [&]<typename Request, typename Response>(
                           void (ShardRouter::*route)(const Request*, Response*,
                                                      ShardRouter::Call)) {
    auto exchange = std::make_shared<Exchange<Request, Response>>();
    if (Status bad = ParseBody(request, name, &exchange->request); !bad.ok()) {
      reply(ApiError(bad));
      return;
    }
    (router_->*route)(&exchange->request, &exchange->response, call(exchange));
  };
  if (method == "topology") {
    auto exchange = std::make_shared<
        Exchange<v1::GetTopologyRequest, v1::GetTopologyResponse>>();
    exchange->request.set_dataset(name);
    router_->GetTopology(&exchange->request, &exchange->response,
                         call(exchange));
  } else if (method == "locate") {
    forward(&ShardRouter::Locate);
  } else if (method == "locateBatch") {
    forward(&ShardRouter::LocateBatch);
  } else if (method == "profile") {
    forward(&ShardRouter::Profile);
  } else {
    forward(&ShardRouter::GridWhole);
  }
}

}  // namespace locator
