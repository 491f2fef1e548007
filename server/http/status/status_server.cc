#include "server/http/status/status_server.h"

#include <boost/beast/core/string.hpp>
#include <chrono>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "server/http/api_error.h"
#include "server/main/server_runner.h"
#include "server/metrics/metrics_text.h"

namespace locator {
namespace {

// Whether `content_type` (a Content-Type value; nullopt if none) is JSON:
// "application/json", parameters such as "; charset=utf-8" allowed.
bool IsJsonContentType(std::optional<std::string_view> content_type) {
  if (!content_type.has_value()) return false;
  std::string_view media = content_type->substr(0, content_type->find(';'));
  while (!media.empty() && (media.back() == ' ' || media.back() == '\t')) {
    media.remove_suffix(1);
  }
  while (!media.empty() && (media.front() == ' ' || media.front() == '\t')) {
    media.remove_prefix(1);
  }
  return boost::beast::iequals(
      boost::beast::string_view(media.data(), media.size()),
      "application/json");
}

}  // namespace

StatusServer::StatusServer(LocatorService* service, HttpOptions options)
    : service_(service),
      options_(std::move(options)),
      registry_(std::make_shared<prometheus::Registry>()),
      rpc_metrics_(registry_.get(), ServerRunner::MethodsServed(
                                        {v1::Locator::service_full_name()})),
      engine_collector_(std::make_shared<EngineCollector>([service] {
        std::vector<DatasetStatsSample> samples;
        for (const auto& slot : service->datasets().slots()) {
          DatasetStatsSample& sample = samples.emplace_back();
          sample.dataset = slot->name();
          v1::GetStatsResponse stats;
          if (service->CurrentStats(slot->name(), &stats).ok()) {
            sample.stats = std::move(stats);
          }
        }
        return samples;
      })),
      endpoints_(StatusSources{
          .authorize =
              options_.public_status
                  ? StatusAuthorizer()
                  : [service](std::optional<std::string_view> authorization) {
                      return service->access_policy().CheckAuthorization(
                          authorization, AccessPolicy::Scope::kData);
                    },
          .stats =
              [service](std::string_view dataset, v1::GetStatsResponse* out) {
                return service->CurrentStats(dataset, out);
              },
          .edges =
              [service](std::string_view dataset, MapEdges* edges) {
                std::shared_ptr<Engine> engine;
                const Status status = service->ServingEngine(dataset, &engine);
                if (!status.ok()) return status;
                edges->segments = engine->EdgeSample();
                edges->boundary = engine->domain_outline().boundary;
                edges->breaklines = engine->domain_outline().breaklines;
                return Status::OK();
              },
          .history =
              [this](std::string_view dataset, const StatsHistory** history) {
                return HistoryOf(dataset, history);
              },
          .metrics_text =
              [this] {
                return MetricsText({registry_, engine_collector_});
              }}),
      cors_(options_.cors_origins),
      api_(service, options_.api, registry_.get()) {
  for (const auto& slot : service->datasets().slots()) {
    histories_.try_emplace(slot->name());
  }
}

StatusServer::~StatusServer() { api_.Shutdown(); }

std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>
StatusServer::NewInterceptorFactory() {
  return rpc_metrics_.NewInterceptorFactory();
}

Status StatusServer::Listen(const std::string& host, int port) {
  return HttpServer::Start(
      host, port, options_.limits,
      [this](HttpRequest request, HttpReply reply) {
        Route(std::move(request), std::move(reply));
      },
      &http_);
}

void StatusServer::Route(HttpRequest request, HttpReply reply) {
  if (cors_.IsPreflight(request)) {
    reply(cors_.Preflight(request));
    return;
  }
  // Every answer carries the CORS headers the request's origin gets.
  std::optional<std::string> origin;
  if (std::optional<std::string_view> header = request.Header("origin")) {
    origin = std::string(*header);
  }
  reply = [this, origin = std::move(origin),
           reply = std::move(reply)](HttpResponse response) {
    cors_.Apply(origin, &response);
    reply(std::move(response));
  };
  if (request.problem != HttpRequest::Problem::kNone) {
    reply(ProblemAnswer(request));
    return;
  }
  if (request.path.starts_with(JsonApi::kPathPrefix)) {
    if (request.method == "POST" &&
        !IsJsonContentType(request.Header("content-type"))) {
      reply(ApiError(grpc::Status(grpc::StatusCode::INVALID_ARGUMENT,
                                  "a POST to the API must have Content-Type: "
                                  "application/json"),
                     415));
      return;
    }
    api_.Handle(std::move(request), std::move(reply));
    return;
  }
  if (request.method != "GET") {
    reply(HttpResponse{.status = 405,
                       .body = "method not allowed\n",
                       .headers = {{"Allow", "GET, HEAD"}}});
    return;
  }
  reply(endpoints_.Handle(request.path, request.query,
                          request.Header("authorization")));
}

HttpResponse StatusServer::ProblemAnswer(const HttpRequest& request) const {
  using Problem = HttpRequest::Problem;
  const auto error = [](grpc::StatusCode code, const std::string& message,
                        unsigned http_status) {
    return ApiError(grpc::Status(code, message), http_status);
  };
  const HttpLimits& limits = options_.limits;
  std::string busy;
  switch (request.problem) {
    case Problem::kBodyTooLarge:
      return error(grpc::StatusCode::RESOURCE_EXHAUSTED,
                   "the request body is larger than this server's limit of " +
                       std::to_string(limits.max_body_bytes) +
                       " bytes (--http-max-body-bytes)",
                   413);
    case Problem::kHeaderTooLarge:
      return error(grpc::StatusCode::RESOURCE_EXHAUSTED,
                   "the request header is larger than this server's limit "
                   "of " +
                       std::to_string(HttpServer::kMaxHeaderBytes) + " bytes",
                   431);
    case Problem::kMalformed:
      return error(grpc::StatusCode::INVALID_ARGUMENT,
                   "malformed HTTP request: " + request.problem_detail, 400);
    case Problem::kAddressFull:
      busy = request.problem_detail + " has " +
             std::to_string(limits.max_connections_per_address) +
             " connections open to this server, its limit "
             "(--http-max-connections-per-address); close one or retry";
      break;
    case Problem::kNone:  // never asked
    case Problem::kServerBusy:
      busy = "all " + std::to_string(limits.max_connections) +
             " connections of this server are busy; retry";
      break;
  }
  return BusyError(busy);
}

Status StatusServer::HistoryOf(std::string_view dataset,
                               const StatsHistory** history) const {
  DatasetSlot* slot = nullptr;
  if (Status found = service_->datasets().Find(dataset, &slot); !found.ok()) {
    return found;
  }
  *history = &histories_.find(slot->name())->second;
  return Status::OK();
}

void StatusServer::SampleHistory() {
  const auto now = std::chrono::system_clock::now();
  for (auto& [name, history] : histories_) {
    v1::GetStatsResponse stats;
    if (!service_->CurrentStats(name, &stats).ok()) continue;
    history.Record(stats.generation(), stats.queries_served(),
                   stats.total_cost(), now);
  }
}

}  // namespace locator
