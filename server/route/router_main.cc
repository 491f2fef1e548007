#include "server/route/router_main.h"

#include <algorithm>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "common/channel_options.h"
#include "server/config/server_log.h"
#include "server/http/cors_policy.h"
#include "server/http/http_frontend.h"
#include "server/main/server_runner.h"
#include "server/metrics/metrics_text.h"
#include "server/metrics/rpc_metrics.h"
#include "server/route/router_http_api.h"
#include "server/route/router_service.h"
#include "server/route/shard_router.h"
#include "server/route/shard_topology.h"

namespace locator {
namespace {

// How long fetching a dataset's topology from the shards may take.
constexpr std::chrono::seconds kTopologyDeadline{10};

}  // namespace

void RunRouter(std::string_view program, const ServerConfig& config) {
  // Replicas behind one target share its calls; a call that never reached
  // a live one is retried (UNAVAILABLE only: it did not run). TLS as the
  // --shard-tls flags say.
  ChannelOptions channel;
  channel.max_message_bytes = static_cast<int>(std::min<size_t>(
      config.serving.max_message_bytes, std::numeric_limits<int>::max()));
  channel.retry_unavailable = true;
  channel.balance_addresses = true;
  channel.security = config.shard_security;
  ShardTopology topology(config.shards, channel, kTopologyDeadline);
  ShardRouter router(&topology, std::max<size_t>(2, config.serving.threads),
                     config.serving.max_batch_points,
                     config.http_max_grid_cells);
  RouterService service(&router, config.serving.transport.default_deadline);
  // With --http-listen, every gRPC call is counted for /metrics, as
  // locatord counts its own.
  auto registry = std::make_shared<prometheus::Registry>();
  std::optional<RpcMetrics> rpc_metrics;
  std::vector<
      std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>>
      interceptors;
  if (config.http_enabled()) {
    rpc_metrics.emplace(
        registry.get(),
        ServerRunner::MethodsServed({v1::Locator::service_full_name()}));
    interceptors.push_back(rpc_metrics->NewInterceptorFactory());
  }
  std::unique_ptr<ServerRunner> runner;
  if (Status started = ServerRunner::Start(program, config.serving, {&service},
                                           std::move(interceptors), &runner);
      !started.ok()) {
    std::cerr << program << ": " << started.message() << std::endl;
    ExitWithoutTeardown(1);
  }
  // For browsers and curl: the routed calls over HTTP/JSON.
  const CorsPolicy cors(config.http_cors_origins);
  const HttpLimits limits{
      .max_body_bytes = config.http_max_body_bytes,
      .max_connections = config.http_max_connections,
      .max_connections_per_address = config.http_max_connections_per_address};
  RouterHttpApi http_api(&router, config.serving.transport.default_deadline,
                         [registry] { return MetricsText({registry}); });
  std::unique_ptr<HttpServer> http;
  if (config.http_enabled()) {
    if (Status listening = HttpServer::Start(
            config.http_host, config.http_port, limits,
            [&](HttpRequest request, HttpReply reply) {
              if (ReceiveRequest(cors, limits, request, &reply)) return;
              http_api.Handle(std::move(request), std::move(reply));
            },
            &http);
        !listening.ok()) {
      std::cerr << program << ": " << listening.message() << std::endl;
      runner->Stop(1);
      ExitWithoutTeardown(runner->Run());
    }
    std::cout << program << " http listening on " << config.http_host << ":"
              << http->port() << std::endl;
  }
  LogLine(LogLevel::kInfo) << "routing to " << config.shards.size()
                           << " shards";
  runner->SetServing(true);
  // What the callbacks refer to here (the shards' channels, the router, its
  // pool) outlives them: the process ends without unwinding this frame.
  ExitWithoutTeardown(runner->Run());
}

}  // namespace locator
