#include "client/shard_routes.h"

#include <string>
#include <utility>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "common/routing/batch_fan_out.h"
#include "common/routing/batch_split.h"
#include "common/status_mapping.h"

namespace locator {

ShardRoutes::ShardRoutes(ShardMap map, std::string crs,
                         std::vector<std::unique_ptr<LocatorClient>> shards)
    : map_(std::move(map)), crs_(std::move(crs)), shards_(std::move(shards)) {}

ShardRoutes::~ShardRoutes() { contexts_.WaitUntilNone(); }

grpc::Status ShardRoutes::Create(const v1::GetTopologyResponse& topology,
                                 const ChannelOptions& channel,
                                 std::chrono::milliseconds deadline,
                                 const RequestScope& scope,
                                 std::unique_ptr<ShardRoutes>* routes) {
  StatusOr<ShardMap> map = ShardMap::FromTopology(topology);
  if (!map.ok()) {
    return grpc::Status(grpc::StatusCode::FAILED_PRECONDITION,
                        map.status().message());
  }
  if (!map->complete()) {
    return grpc::Status(
        grpc::StatusCode::FAILED_PRECONDITION,
        "the topology of dataset '" + map->dataset() +
            "' is incomplete (some tiles have no shard): ask a router "
            "(locatord --route) for it, or call it without routing");
  }
  std::vector<std::unique_ptr<LocatorClient>> shards;
  for (size_t s = 0; s < map->num_shards(); ++s) {
    ChannelOptions options = channel;
    if (!map->target(s).empty()) options.target = map->target(s);
    shards.push_back(std::make_unique<LocatorClient>(
        CreateLocatorChannel(options), deadline, scope));
  }
  routes->reset(new ShardRoutes(*std::move(map), scope.crs, std::move(shards)));
  return grpc::Status::OK;
}

LocatorClient& ShardRoutes::ClientFor(const Point2& point) const {
  Point2 at = point;
  // A point PROJ cannot map is refused by any shard, in the same words.
  if (!crs_.empty() &&
      !gis::RequestPointsToDataset(crs_, map_.crs(), {&at, 1}).ok()) {
    return *shards_[0];
  }
  return *shards_[map_.ShardOf(at)];
}

void ShardRoutes::StartLocateBatch(const v1::LocateBatchRequest* request,
                                   v1::LocateBatchResponse* response,
                                   Completion done) const {
  std::vector<Point2> where;
  if (!request->crs().empty()) {
    for (int i = 0; i < request->xs_size(); ++i) {
      where.push_back({request->xs(i), request->ys(i)});
    }
    if (Status status =
            gis::RequestPointsToDataset(request->crs(), map_.crs(), where);
        !status.ok()) {
      done(ToGrpcStatus(status));
      return;
    }
  }
  BatchSplit split;
  if (Status status = SplitBatch(*request, map_, &split, where); !status.ok()) {
    done(ToGrpcStatus(status));
    return;
  }
  ShardCalls calls;
  calls.new_context = [this] {
    return contexts_.Counted(std::make_unique<grpc::ClientContext>());
  };
  calls.start = [this](size_t shard, grpc::ClientContext* context,
                       v1::LocateBatchRequest* part,
                       v1::LocateBatchResponse* answer, ShardCalls::Done done) {
    shards_[shard]->StartLocateBatch(context, part, answer, std::move(done));
  };
  calls.target = [this](size_t shard) { return map_.target(shard); };
  calls.run_merge = [](std::function<void()> merge) { merge(); };
  FanOutBatch(request, std::move(split), response, std::move(calls),
              std::move(done));
}

}  // namespace locator
