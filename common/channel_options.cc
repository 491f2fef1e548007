#include "common/channel_options.h"

#include <grpcpp/support/client_interceptor.h>

#include <utility>
#include <vector>

namespace locator {
namespace {

// Retries UNAVAILABLE only: it means the call never reached a live server
// (connection refused or reset while it restarts), so even Retune is safe to
// send again. Backoff 50 ms doubling to 1 s covers a typical restart.
constexpr char kRetryMethodConfig[] = R"json(
  "methodConfig": [{
    "name": [{"service": "locator.v1.Locator"},
             {"service": "grpc.health.v1.Health"}],
    "retryPolicy": {
      "maxAttempts": 5,
      "initialBackoff": "0.05s",
      "maxBackoff": "1s",
      "backoffMultiplier": 2,
      "retryableStatusCodes": ["UNAVAILABLE"]
    }
  }])json";
constexpr char kRoundRobinConfig[] = R"json(
  "loadBalancingConfig": [{"round_robin": {}}])json";

// The service config `options` ask for; empty: none.
std::string ServiceConfig(const ChannelOptions& options) {
  std::string parts;
  if (options.retry_unavailable) parts += kRetryMethodConfig;
  if (options.balance_addresses) {
    if (!parts.empty()) parts += ",";
    parts += kRoundRobinConfig;
  }
  return parts.empty() ? "" : "{" + parts + "}";
}

// Adds the authorization header to a call's initial metadata. (gRPC's call
// credentials would do the same, but refuse to travel over plaintext.)
class BearerTokenInterceptor final : public grpc::experimental::Interceptor {
 public:
  explicit BearerTokenInterceptor(std::string header)
      : header_(std::move(header)) {}

  void Intercept(
      grpc::experimental::InterceptorBatchMethods* methods) override {
    if (methods->QueryInterceptionHookPoint(
            grpc::experimental::InterceptionHookPoints::
                PRE_SEND_INITIAL_METADATA)) {
      methods->GetSendInitialMetadata()->emplace("authorization", header_);
    }
    methods->Proceed();
  }

 private:
  const std::string header_;
};

class BearerTokenInterceptorFactory final
    : public grpc::experimental::ClientInterceptorFactoryInterface {
 public:
  explicit BearerTokenInterceptorFactory(const std::string& token)
      : header_("Bearer " + token) {}

  grpc::experimental::Interceptor* CreateClientInterceptor(
      grpc::experimental::ClientRpcInfo* /*info*/) override {
    return new BearerTokenInterceptor(header_);
  }

 private:
  const std::string header_;
};

std::shared_ptr<grpc::ChannelCredentials> Credentials(
    const ChannelSecurity& security) {
  if (!security.tls) return grpc::InsecureChannelCredentials();
  grpc::SslCredentialsOptions options;
  options.pem_root_certs = security.root_pem;
  options.pem_cert_chain = security.cert_chain_pem;
  options.pem_private_key = security.private_key_pem;
  return grpc::SslCredentials(options);
}

}  // namespace

std::shared_ptr<grpc::Channel> CreateLocatorChannel(
    const ChannelOptions& options) {
  grpc::ChannelArguments args;
  args.SetMaxReceiveMessageSize(options.max_message_bytes);
  args.SetMaxSendMessageSize(options.max_message_bytes);
  if (const std::string config = ServiceConfig(options); !config.empty()) {
    args.SetServiceConfigJSON(config);
  }
  if (options.own_connection) {
    // Channels with equal arguments share subchannels (and so one TCP
    // connection) through the global pool; a local pool gives each its own.
    args.SetInt(GRPC_ARG_USE_LOCAL_SUBCHANNEL_POOL, 1);
  }
  const ChannelSecurity& security = options.security;
  if (!security.server_name.empty()) {
    args.SetSslTargetNameOverride(security.server_name);
  }
  std::vector<
      std::unique_ptr<grpc::experimental::ClientInterceptorFactoryInterface>>
      interceptors;
  if (!security.bearer_token.empty()) {
    interceptors.push_back(
        std::make_unique<BearerTokenInterceptorFactory>(security.bearer_token));
  }
  return grpc::experimental::CreateCustomChannelWithInterceptors(
      options.target, Credentials(security), args, std::move(interceptors));
}

}  // namespace locator
