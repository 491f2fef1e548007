#include "server/route/router_main.h"

#include <algorithm>
#include <iostream>
#include <limits>
#include <memory>

#include "common/channel_options.h"
#include "server/config/server_log.h"
#include "server/main/server_runner.h"
#include "server/route/router_service.h"
#include "server/route/shard_topology.h"

namespace locator {
namespace {

// How long fetching a dataset's topology from the shards may take.
constexpr std::chrono::seconds kTopologyDeadline{10};

}  // namespace

int RunRouter(std::string_view program, const ServerConfig& config) {
  // Replicas behind one target share its calls; a call that never reached
  // a live one is retried (UNAVAILABLE only: it did not run).
  ChannelOptions channel;
  channel.max_message_bytes = static_cast<int>(std::min<size_t>(
      config.serving.max_message_bytes, std::numeric_limits<int>::max()));
  channel.retry_unavailable = true;
  channel.balance_addresses = true;
  ShardTopology topology(config.shards, channel, kTopologyDeadline);
  RouterService service(&topology, std::max<size_t>(2, config.serving.threads),
                        config.serving.transport.default_deadline,
                        config.serving.max_batch_points);
  std::unique_ptr<ServerRunner> runner;
  if (Status started =
          ServerRunner::Start(program, config.serving, {&service}, {}, &runner);
      !started.ok()) {
    std::cerr << program << ": " << started.message() << std::endl;
    return 1;
  }
  LogLine(LogLevel::kInfo) << "routing to " << config.shards.size()
                           << " shards";
  runner->SetServing(true);
  return runner->Run();
}

}  // namespace locator
