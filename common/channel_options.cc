#include "common/channel_options.h"

#include <grpcpp/support/client_interceptor.h>

#include <utility>
#include <vector>

#include "common/credential_files.h"

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

void AddChannelSecurityFlags(ChannelSecurityFlags* security_flags,
                             FlagSet* flags) {
  ChannelSecurityFlags& f = *security_flags;
  flags->Add("token-file", flag::Text(&f.token_file).Shape("FILE"),
             "send this file's token as 'authorization: Bearer <token>' on "
             "every call");
  flags->Add("tls", flag::Switch(&f.tls),
             "speak TLS (implied by the other --tls flags); without --tls-ca, "
             "trust the system's roots");
  flags->Add("tls-ca", flag::Text(&f.tls_ca).Shape("FILE"),
             "trust servers whose certificate this PEM CA signed");
  flags->Add("tls-cert", flag::Text(&f.tls_cert).Shape("FILE"),
             "mutual TLS: present this PEM certificate chain (needs "
             "--tls-key)");
  flags->Add("tls-key", flag::Text(&f.tls_key).Shape("FILE"),
             "PEM private key of --tls-cert (unencrypted)");
  flags->Add("tls-server-name", flag::Text(&f.tls_server_name).Shape("NAME"),
             "check the server's certificate against this name instead of the "
             "target's host");
}

Status LoadChannelSecurity(const ChannelSecurityFlags& flags,
                           ChannelSecurity* security) {
  *security = ChannelSecurity();
  security->tls = flags.tls || !flags.tls_ca.empty() ||
                  !flags.tls_cert.empty() || !flags.tls_server_name.empty();
  security->server_name = flags.tls_server_name;
  KeyPairPem pair;
  Status status = ReadKeyPairFiles(flags.tls_cert, flags.tls_key, &pair);
  security->cert_chain_pem = std::move(pair.cert_chain);
  security->private_key_pem = std::move(pair.private_key);
  if (status.ok() && !flags.token_file.empty()) {
    status =
        ReadTokenFile("token-file", flags.token_file, &security->bearer_token);
  }
  if (status.ok() && !flags.tls_ca.empty()) {
    status = ReadPemFile("tls-ca", flags.tls_ca, PemKind::kCertificates,
                         &security->root_pem);
  }
  return status;
}

}  // namespace locator
