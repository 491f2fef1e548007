// ShardRoutes: how a LocatorClient that routes (LocatorClient::
// RouteByTopology, `locator --route`, `locator-load --route`) reaches the
// shards of a tiled dataset: a client per shard, and the dataset's shard
// map. A Locate goes to the shard of its point; a LocateBatch is split by
// shard (common/routing/batch_split.h), the parts sent at once, each with
// a context of its own and the client's deadline, and the answers merged in
// input order; the first failing part cancels the others. Points in the
// scope's crs are routed where PROJ puts them in the dataset's CRS
// (gis::RequestPointsToDataset, as a shard maps them) and sent as they are.
//
// Counts the contexts of the calls it starts, and outlives them: see
// common/in_flight.h for why the last hold on a channel must not be let go
// on a gRPC thread.
//
// Thread-safety: immutable after Create() but for that count; calls may
// start from any thread.

#ifndef LOCATOR_CLIENT_SHARD_ROUTES_H_
#define LOCATOR_CLIENT_SHARD_ROUTES_H_

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "client/locator_client.h"
#include "common/channel_options.h"
#include "common/in_flight.h"
#include "common/routing/shard_map.h"
#include "locator/v1/locator.grpc.pb.h"

namespace locator {

class ShardRoutes {
 public:
  using Completion = LocatorClient::Completion;

  // The routes of `topology`: a client per shard over a channel made with
  // `channel` (target replaced by the shard's; an empty one is
  // `channel.target`), each with `deadline` and `scope`. FAILED_PRECONDITION
  // when the topology is malformed or incomplete (a client cannot reach the
  // tiles no shard serves: go through a router).
  // Waits until the context of every call started has been deleted.
  ~ShardRoutes();

  ShardRoutes(const ShardRoutes&) = delete;
  ShardRoutes& operator=(const ShardRoutes&) = delete;

  static grpc::Status Create(const v1::GetTopologyResponse& topology,
                             const ChannelOptions& channel,
                             std::chrono::milliseconds deadline,
                             const RequestScope& scope,
                             std::unique_ptr<ShardRoutes>* routes);
  // The client of the shard serving `point`.
  LocatorClient& ClientFor(const Point2& point) const;
  // Starts `request` (scope applied) split by shard; `done` runs once the
  // merged answer is in *response or a part failed. `request` and
  // `response` must live until then.
  void StartLocateBatch(const v1::LocateBatchRequest* request,
                        v1::LocateBatchResponse* response,
                        Completion done) const;

 private:
  ShardRoutes(ShardMap map, std::string crs,
              std::vector<std::unique_ptr<LocatorClient>> shards);

  const ShardMap map_;
  const std::string crs_;  // the scope's: the CRS of the points routed
  const std::vector<std::unique_ptr<LocatorClient>> shards_;
  mutable InFlight contexts_;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_SHARD_ROUTES_H_
