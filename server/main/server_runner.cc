#include "server/main/server_runner.h"

#include <google/protobuf/descriptor.h>
#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/health_check_service_interface.h>

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <utility>

#include "locator/v1/locator.grpc.pb.h"

namespace locator {
namespace {

std::shared_ptr<grpc::ServerCredentials> Credentials(const TlsConfig& tls) {
  if (!tls.enabled()) return grpc::InsecureServerCredentials();
  grpc::SslServerCredentialsOptions options(
      tls.client_ca_pem.empty()
          ? GRPC_SSL_DONT_REQUEST_CLIENT_CERTIFICATE
          : GRPC_SSL_REQUEST_AND_REQUIRE_CLIENT_CERTIFICATE_AND_VERIFY);
  options.pem_root_certs = tls.client_ca_pem;
  options.pem_key_cert_pairs.push_back(
      {tls.private_key_pem, tls.cert_chain_pem});
  return grpc::SslServerCredentials(options);
}

void SetConnectionLimits(const TransportConfig& transport,
                         grpc::ServerBuilder* builder) {
  builder->AddChannelArgument(GRPC_ARG_MAX_CONCURRENT_STREAMS,
                              transport.max_concurrent_streams);
  // With bandwidth-delay probing, gRPC grows a stream's receive window to
  // many megabytes, and a client that writes without reading its answers
  // fills it: 4 such streams grew the server by ~50 MB. Without it each
  // stream's window stays at the 64 KiB lookahead, so a connection buffers
  // at most max_concurrent_streams x 64 KiB. (1M-point batches over
  // loopback ran as fast either way.)
  builder->AddChannelArgument(GRPC_ARG_HTTP2_BDP_PROBE, 0);
  builder->AddChannelArgument(GRPC_ARG_KEEPALIVE_TIME_MS,
                              transport.keepalive_time_ms);
  builder->AddChannelArgument(GRPC_ARG_KEEPALIVE_TIMEOUT_MS,
                              transport.keepalive_timeout_ms);
  // Pooled clients keep idle connections warm through load balancers; they
  // may, at the minimum interval. The server's own pings then also find
  // dead peers on idle connections.
  builder->AddChannelArgument(GRPC_ARG_KEEPALIVE_PERMIT_WITHOUT_CALLS, 1);
  builder->AddChannelArgument(
      GRPC_ARG_HTTP2_MIN_RECV_PING_INTERVAL_WITHOUT_DATA_MS,
      transport.min_ping_interval_ms);
  builder->AddChannelArgument(GRPC_ARG_HTTP2_MAX_PING_STRIKES,
                              transport.max_ping_strikes);
}

// The methods of the services Start() adds, in this gRPC's version (the
// default health service is not a protobuf-generated one, so no descriptor
// lists them). A method a later gRPC adds is counted as unknown until it is
// listed here.
constexpr std::string_view kBuiltInMethods[] = {
    "/grpc.health.v1.Health/Check",
    "/grpc.health.v1.Health/Watch",
    "/grpc.reflection.v1alpha.ServerReflection/ServerReflectionInfo",
};

}  // namespace

std::vector<std::string> ServerRunner::MethodsServed(
    const std::vector<std::string_view>& services) {
  std::vector<std::string> methods(std::begin(kBuiltInMethods),
                                   std::end(kBuiltInMethods));
  for (const std::string_view name : services) {
    const google::protobuf::ServiceDescriptor* service =
        google::protobuf::DescriptorPool::generated_pool()->FindServiceByName(
            std::string(name));
    for (int i = 0; service != nullptr && i < service->method_count(); ++i) {
      methods.push_back("/" + service->full_name() + "/" +
                        service->method(i)->name());
    }
  }
  return methods;
}

ServerRunner::ServerRunner(std::string_view program)
    : program_(program),
      signals_(io_context_, SIGINT, SIGTERM),
      hangup_(io_context_, SIGHUP) {}

Status ServerRunner::Start(
    std::string_view program, const ServingConfig& config,
    const std::vector<grpc::Service*>& services,
    std::vector<
        std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>>
        interceptors,
    std::unique_ptr<ServerRunner>* runner) {
  // The signal handlers are installed (by the constructor) before the
  // listening line goes out: whoever reads that line may signal at once.
  std::unique_ptr<ServerRunner> created(new ServerRunner(program));

  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  int port = 0;
  builder.AddListeningPort(config.ListenAddress(),
                           Credentials(config.transport.tls), &port);
  builder.SetMaxReceiveMessageSize(static_cast<int>(config.max_message_bytes));
  builder.SetMaxSendMessageSize(static_cast<int>(config.max_message_bytes));
  // gRPC sets SO_REUSEPORT by default, so a second server could bind the
  // same port and silently take a share of the connections. Without it, an
  // address in use fails here.
  builder.AddChannelArgument(GRPC_ARG_ALLOW_REUSEPORT, 0);
  SetConnectionLimits(config.transport, &builder);
  for (grpc::Service* service : services) builder.RegisterService(service);
  builder.experimental().SetInterceptorCreators(std::move(interceptors));
  created->server_ = builder.BuildAndStart();
  if (created->server_ == nullptr || port == 0) {
    return Status::Unavailable(
        "cannot listen on " + config.ListenAddress() +
        ": the address is in use or not this machine's (gRPC's error above "
        "says which)");
  }
  created->SetServing(false);
  std::cout << program << " listening on " << config.listen_host << ":" << port
            << std::endl;
  *runner = std::move(created);
  return Status::OK();
}

void ServerRunner::SetServing(bool serving) {
  grpc::HealthCheckServiceInterface* health = server_->GetHealthCheckService();
  health->SetServingStatus("", serving);
  health->SetServingStatus(v1::Locator::service_full_name(), serving);
}

void ServerRunner::OnDrain(DrainHook hook) {
  drain_hooks_.push_back(std::move(hook));
}

void ServerRunner::RunEvery(double seconds, std::function<void()> tick) {
  const auto period =
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(seconds));
  ScheduleTick(&timers_.emplace_back(io_context_), period, std::move(tick));
}

void ServerRunner::ScheduleTick(boost::asio::steady_timer* timer,
                                std::chrono::steady_clock::duration period,
                                std::function<void()> tick) {
  timer->expires_after(period);
  timer->async_wait([this, timer, period, tick = std::move(tick)](
                        const boost::system::error_code& error) mutable {
    if (error) return;  // cancelled: the loop is stopping
    tick();
    ScheduleTick(timer, period, std::move(tick));
  });
}

void ServerRunner::Stop(int exit_code) {
  exit_code_ = exit_code;
  SetServing(false);
  // The hooks and Shutdown() block the loop until the in-flight calls are
  // done (or cut off at the deadline); nothing else is left for the loop to
  // do by then.
  const auto deadline = std::chrono::system_clock::now() + kDrainDeadline;
  for (const DrainHook& hook : drain_hooks_) hook(deadline);
  server_->Shutdown(deadline);
  io_context_.stop();
}

void ServerRunner::OnHangup(std::function<void()> handler) {
  hangup_handler_ = std::move(handler);
}

void ServerRunner::BeforeExit(std::function<void()> hook) {
  before_exit_ = std::move(hook);
}

void ServerRunner::WaitForHangup() {
  hangup_.async_wait([this](const boost::system::error_code& error, int) {
    if (error) return;  // cancelled: the loop is stopping
    if (hangup_handler_) {
      hangup_handler_();
    } else {
      std::cerr << program_ << " received SIGHUP; nothing to do" << std::endl;
    }
    WaitForHangup();
  });
}

int ServerRunner::Run() {
  WaitForHangup();
  signals_.async_wait(
      [this](const boost::system::error_code& error, int signal_number) {
        if (error) return;
        std::cerr << program_ << " received signal " << signal_number
                  << ", draining in-flight calls" << std::endl;
        Stop(0);
      });
  io_context_.run();
  // Every call has been answered and the server is shut down; the hook saves
  // whatever state is worth keeping.
  if (before_exit_) before_exit_();
  return exit_code_;
}

void ExitWithoutTeardown(int exit_code) {
  std::cout.flush();
  std::cerr.flush();
  std::_Exit(exit_code);
}

}  // namespace locator
