// ClientPool: the channels a load run spreads its calls over, each on a TCP
// connection of its own, with a LocatorClient on each.
//
// Calls on one HTTP/2 connection share its framing and flow control, and
// each side reads a connection on one thread at a time: more connections
// let client and server use more cores.
//
// Owns the channels and clients. Thread-safety: thread-safe.

#ifndef LOCATOR_CLIENT_LOAD_CLIENT_POOL_H_
#define LOCATOR_CLIENT_LOAD_CLIENT_POOL_H_

#include <grpcpp/grpcpp.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

#include "client/locator_client.h"

namespace locator {

class ClientPool {
 public:
  // `channels` (> 0) channels to options.target; every call gets `deadline`
  // and every request `scope`.
  ClientPool(const ChannelOptions& options, size_t channels,
             std::chrono::milliseconds deadline,
             const RequestScope& scope = {});

  size_t size() const { return clients_.size(); }
  std::chrono::milliseconds deadline() const { return deadline_; }
  // The index of the channel for the next call, round-robin.
  size_t NextIndex() { return next_.fetch_add(1) % clients_.size(); }
  const std::shared_ptr<grpc::Channel>& channel(size_t i) const {
    return channels_[i];
  }
  LocatorClient& client(size_t i) { return *clients_[i]; }
  // The client for the next call, round-robin.
  LocatorClient& NextClient() { return client(NextIndex()); }
  // Makes every client route Locate and LocateBatch straight to the shards
  // (LocatorClient::RouteByTopology), each over channels of its own. The
  // first client's error.
  grpc::Status RouteByTopology();

 private:
  const std::chrono::milliseconds deadline_;
  ChannelOptions channel_;  // of every channel, own_connection set
  std::vector<std::shared_ptr<grpc::Channel>> channels_;
  std::vector<std::unique_ptr<LocatorClient>> clients_;
  std::atomic<size_t> next_{0};
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_CLIENT_POOL_H_
