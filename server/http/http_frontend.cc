#include "server/http/http_frontend.h"

#include <boost/beast/core/string.hpp>
#include <chrono>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "server/http/api_error.h"
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

// The answer to a request the HTTP server could not read.
HttpResponse ProblemAnswer(const HttpRequest& request,
                           const HttpLimits& limits) {
  using Problem = HttpRequest::Problem;

  std::string busy;
  switch (request.problem) {
    case Problem::kBodyTooLarge:
      return ApiError(Status::ResourceExhausted(
                          "the request body is larger than this server's "
                          "limit of " +
                          std::to_string(limits.max_body_bytes) +
                          " bytes (--http-max-body-bytes)"),
                      413);
    case Problem::kHeaderTooLarge:
      return ApiError(
          Status::ResourceExhausted(
              "the request header is larger than this server's "
              "limit of " +
              std::to_string(HttpServer::kMaxHeaderBytes) + " bytes"),
          431);
    case Problem::kMalformed:
      return ApiError(Status::InvalidArgument("malformed HTTP request: " +
                                              request.problem_detail),
                      400);
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

}  // namespace

HttpFrontend::HttpFrontend(LocatorApp* app, HttpOptions options,
                           std::shared_ptr<prometheus::Registry> registry)
    : app_(app),
      options_(std::move(options)),
      registry_(std::move(registry)),
      engine_collector_(std::make_shared<EngineCollector>([app] {
        std::vector<DatasetStatsSample> samples;
        for (const auto& slot : app->datasets().slots()) {
          DatasetStatsSample& sample = samples.emplace_back();
          sample.dataset = slot->name();
          if (StatusOr<v1::GetStatsResponse> stats =
                  app->CurrentStats(slot->name());
              stats.ok()) {
            sample.stats = *std::move(stats);
          }
        }
        return samples;
      })),
      endpoints_(StatusSources{
          .authorize =
              options_.public_status
                  ? StatusAuthorizer()
                  : [app](std::optional<std::string_view> authorization) {
                      return app->access_policy().CheckAuthorization(
                          authorization, AccessPolicy::Scope::kData);
                    },
          .stats =
              [app](std::string_view dataset, v1::GetStatsResponse* out) {
                StatusOr<v1::GetStatsResponse> stats =
                    app->CurrentStats(dataset);
                if (!stats.ok()) return stats.status();
                *out = *std::move(stats);
                return Status::OK();
              },
          .edges =
              [app](std::string_view dataset, MapEdges* edges) {
                StatusOr<std::shared_ptr<Engine>> engine =
                    app->ServingEngine(dataset);
                if (!engine.ok()) return engine.status();
                edges->segments = (*engine)->EdgeSample();
                edges->boundary = (*engine)->domain_outline().boundary;
                edges->breaklines = (*engine)->domain_outline().breaklines;
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
      api_(app, options_.api, registry_.get()),
      open_topo_data_(app, &api_),
      edr_(app, &api_) {
  for (const auto& slot : app->datasets().slots()) {
    histories_.try_emplace(slot->name());
  }
}

HttpFrontend::~HttpFrontend() { api_.Shutdown(); }

Status HttpFrontend::Listen(const std::string& host, int port) {
  return HttpServer::Start(
      host, port, options_.limits,
      [this](HttpRequest request, HttpReply reply) {
        Route(std::move(request), std::move(reply));
      },
      &http_);
}

bool ReceiveRequest(const CorsPolicy& cors, const HttpLimits& limits,
                    const HttpRequest& request, HttpReply* reply) {
  if (cors.IsPreflight(request)) {
    (*reply)(cors.Preflight(request));
    return true;
  }
  // Every answer carries the CORS headers the request's origin gets.
  std::optional<std::string> origin;
  if (std::optional<std::string_view> header = request.Header("origin")) {
    origin = std::string(*header);
  }
  *reply = [&cors, origin = std::move(origin),
            reply = std::move(*reply)](HttpResponse response) {
    cors.Apply(origin, &response);
    reply(std::move(response));
  };
  if (request.problem != HttpRequest::Problem::kNone) {
    (*reply)(ProblemAnswer(request, limits));
    return true;
  }
  if (request.method == "POST" &&
      request.path.starts_with(JsonApi::kPathPrefix) &&
      !IsJsonContentType(request.Header("content-type"))) {
    (*reply)(ApiError(Status::InvalidArgument("a POST to the API must have "
                                              "Content-Type: application/json"),
                      415));
    return true;
  }
  return false;
}

void HttpFrontend::Route(HttpRequest request, HttpReply reply) {
  if (ReceiveRequest(cors_, options_.limits, request, &reply)) return;
  // Open Topo Data takes form-encoded POSTs as its clients send them; its
  // calls only read, and a token travels in a header no form can set.
  if (request.path == OpenTopoDataApi::kPathPrefix ||
      request.path.starts_with(std::string(OpenTopoDataApi::kPathPrefix) +
                               "/")) {
    open_topo_data_.Handle(std::move(request), std::move(reply));
    return;
  }
  if (EdrApi::Serves(request.path)) {
    edr_.Handle(std::move(request), std::move(reply));
    return;
  }
  if (request.path.starts_with(JsonApi::kPathPrefix)) {
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

Status HttpFrontend::HistoryOf(std::string_view dataset,
                               const StatsHistory** history) const {
  DatasetSlot* slot = nullptr;
  if (Status found = app_->datasets().Find(dataset, &slot); !found.ok()) {
    return found;
  }
  *history = &histories_.find(slot->name())->second;
  return Status::OK();
}

void HttpFrontend::SampleHistory() {
  const auto now = std::chrono::system_clock::now();
  for (auto& [name, history] : histories_) {
    StatusOr<v1::GetStatsResponse> stats = app_->CurrentStats(name);
    if (!stats.ok()) continue;
    history.Record(stats->generation(), stats->queries_served(),
                   stats->total_cost(), now);
  }
}

}  // namespace locator
