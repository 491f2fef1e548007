// ChannelOptions: how a client (`locator`, `locator-load`, the router, the
// tests) reaches
// a locator server (address, message limit, retries, TLS, bearer token), and
// CreateLocatorChannel, which builds a channel from them.
//
// The security flags --token-file, --tls, --tls-ca, --tls-cert, --tls-key
// and --tls-server-name are declared and read here, once for both binaries
// (AddChannelSecurityFlags, LoadChannelSecurity). The token goes on every
// call made over the channel, health checks included, through a client
// interceptor: no call site can forget it.
//
// Thread-safety: plain values and free functions; channels are thread-safe.

#ifndef LOCATOR_COMMON_CHANNEL_OPTIONS_H_
#define LOCATOR_COMMON_CHANNEL_OPTIONS_H_

#include <grpcpp/grpcpp.h>

#include <memory>
#include <string>

#include "common/flags/flag_set.h"
#include "locator/status.h"

namespace locator {

// Credentials, as read from the files the flags name.
struct ChannelSecurity {
  // Sent as "authorization: Bearer <token>" on every call; empty: none.
  std::string bearer_token;
  // Speak TLS. Without root_pem, gRPC's default roots are trusted.
  bool tls = false;
  std::string root_pem;
  // The client's certificate chain and key, for mutual TLS.
  std::string cert_chain_pem;
  std::string private_key_pem;
  // The name the server's certificate is checked against instead of the
  // target's host (e.g. "localhost" when dialling 127.0.0.1).
  std::string server_name;
};

struct ChannelOptions {
  std::string target = "127.0.0.1:50051";
  // Limit on messages in both directions; large batches need more than
  // gRPC's default of 4 MiB.
  int max_message_bytes = 64 << 20;
  // Retry calls that fail with UNAVAILABLE (a restarting server), with
  // exponential backoff, through a gRPC service config.
  bool retry_unavailable = false;
  // Open a TCP connection of this channel's own instead of sharing one with
  // other channels to the same target.
  bool own_connection = false;
  // Spread calls round-robin over every address the target resolves to
  // (a Kubernetes headless Service's replicas) instead of using the first.
  bool balance_addresses = false;
  ChannelSecurity security = {};
};

// A channel to options.target: TLS or plaintext, with the bearer token.
std::shared_ptr<grpc::Channel> CreateLocatorChannel(
    const ChannelOptions& options);

// The security flags as typed.
struct ChannelSecurityFlags {
  std::string token_file;
  bool tls = false;
  std::string tls_ca;
  std::string tls_cert;
  std::string tls_key;
  std::string tls_server_name;
};

// Declares the security flags on `flags`, into `security_flags`, which
// must outlive the parse.
void AddChannelSecurityFlags(ChannelSecurityFlags* security_flags,
                             FlagSet* flags);

// Reads the files the flags name into `security`. InvalidArgument naming
// the flag and the file when one cannot be read or does not parse, or when
// the flags do not go together.
Status LoadChannelSecurity(const ChannelSecurityFlags& flags,
                           ChannelSecurity* security);

}  // namespace locator

#endif  // LOCATOR_COMMON_CHANNEL_OPTIONS_H_
