#include "client/load/client_pool.h"

namespace locator {

ClientPool::ClientPool(const ChannelOptions& options, size_t channels,
                       std::chrono::milliseconds deadline,
                       const RequestScope& scope)
    : deadline_(deadline), channel_(options) {
  channel_.own_connection = true;
  for (size_t i = 0; i < channels; ++i) {
    channels_.push_back(CreateLocatorChannel(channel_));
    clients_.push_back(
        std::make_unique<LocatorClient>(channels_.back(), deadline, scope));
  }
}

ClientPool::~ClientPool() { calls_.WaitUntilNone(); }

grpc::Status ClientPool::RouteByTopology() {
  for (const std::unique_ptr<LocatorClient>& client : clients_) {
    if (grpc::Status status = client->RouteByTopology(channel_); !status.ok()) {
      return status;
    }
  }
  return grpc::Status::OK;
}

}  // namespace locator
