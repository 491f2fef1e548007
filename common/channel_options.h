// ChannelOptions: how a client (`locator`, `locator-load`, the router, the
// tests) reaches a locator server (address, message limit, retries, TLS,
// bearer token), and CreateLocatorChannel, which builds a channel from them.
//
// The security and its flags are in channel_security.h. The token goes on
// every call made over the channel, health checks included, through a
// client interceptor: no call site can forget it.
//
// Thread-safety: plain values and free functions; channels are thread-safe.

#ifndef LOCATOR_COMMON_CHANNEL_OPTIONS_H_
#define LOCATOR_COMMON_CHANNEL_OPTIONS_H_

#include <grpcpp/grpcpp.h>

#include <memory>
#include <string>

#include "common/channel_security.h"

namespace locator {

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

}  // namespace locator

#endif  // LOCATOR_COMMON_CHANNEL_OPTIONS_H_
