#include "client/load/client_pool.h"

namespace locator {

ClientPool::ClientPool(const ChannelOptions& options, size_t channels,
                       std::chrono::milliseconds deadline,
                       const RequestScope& scope)
    : deadline_(deadline) {
  ChannelOptions own = options;
  own.own_connection = true;
  for (size_t i = 0; i < channels; ++i) {
    channels_.push_back(CreateLocatorChannel(own));
    clients_.push_back(
        std::make_unique<LocatorClient>(channels_.back(), deadline, scope));
  }
}

}  // namespace locator
