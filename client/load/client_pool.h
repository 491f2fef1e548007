// ClientPool: the channels a load run spreads its calls over, each on a TCP
// connection of its own, with a LocatorClient on each.
//
// Calls on one HTTP/2 connection share its framing and flow control, and
// each side reads a connection on one thread at a time: more connections
// let client and server use more cores.
//
// Owns the channels and clients, and counts the call objects made on them
// (NewCall) so as to outlive them: see common/in_flight.h for why the last
// hold on a channel must not be let go on a gRPC thread.
//
// Thread-safety: thread-safe.

#ifndef LOCATOR_CLIENT_LOAD_CLIENT_POOL_H_
#define LOCATOR_CLIENT_LOAD_CLIENT_POOL_H_

#include <grpcpp/grpcpp.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

#include "client/locator_client.h"
#include "common/in_flight.h"

namespace locator {

class ClientPool {
 public:
  // `channels` (> 0) channels to options.target; every call gets `deadline`
  // and every request `scope`.
  ClientPool(const ChannelOptions& options, size_t channels,
             std::chrono::milliseconds deadline,
             const RequestScope& scope = {});
  // Waits until every call from NewCall() has been deleted.
  ~ClientPool();

  ClientPool(const ClientPool&) = delete;
  ClientPool& operator=(const ClientPool&) = delete;

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
  // A new call object (one that holds a grpc::ClientContext), counted until
  // it is deleted.
  template <typename Call>
  std::shared_ptr<Call> NewCall() {
    return calls_.Counted(std::make_unique<Call>());
  }
  // Makes every client route Locate and LocateBatch straight to the shards
  // (LocatorClient::RouteByTopology), each over channels of its own. The
  // first client's error.
  grpc::Status RouteByTopology();

 private:
  const std::chrono::milliseconds deadline_;
  InFlight calls_;
  ChannelOptions channel_;  // of every channel, own_connection set
  std::vector<std::shared_ptr<grpc::Channel>> channels_;
  std::vector<std::unique_ptr<LocatorClient>> clients_;
  std::atomic<size_t> next_{0};
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_CLIENT_POOL_H_
