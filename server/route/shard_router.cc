#include "server/route/shard_router.h"

#include <utility>
#include <vector>

#include "common/gis/crs_transformer.h"
#include "common/routing/batch_fan_out.h"
#include "common/routing/batch_split.h"
#include "common/status_mapping.h"
#include "server/app/batch_locator.h"
#include "server/route/grid_collector.h"

namespace locator {
namespace {

// Batches up to this many points are split and merged on the calling
// thread (as short as routing one point); larger ones on the pool.
constexpr int kInlineBatchPoints = 4096;

}  // namespace

grpc::Status FromShard(const ShardTopology& topology, size_t shard,
                       const grpc::Status& status) {
  return FromShard(shard, topology.target(shard), status);
}

ShardRouter::ShardRouter(ShardTopology* topology, size_t threads,
                         size_t max_batch_points, uint64_t max_whole_grid_cells)
    : topology_(topology),
      max_batch_points_(max_batch_points),
      max_whole_grid_cells_(max_whole_grid_cells),
      pool_(threads) {}

void ShardRouter::WithTopology(
    const std::string& dataset, bool here, const Call& call,
    std::function<void(const ShardTopology::Routed& routed)> route) {
  if (here) {
    if (std::shared_ptr<const ShardTopology::Routed> routed =
            topology_->Known(dataset)) {
      route(*routed);
      return;
    }
  }
  // Fetching the topology waits on the shards.
  pool_.Submit([this, dataset, call, route = std::move(route)] {
    std::shared_ptr<const ShardTopology::Routed> routed;
    if (grpc::Status status =
            topology_->Get(dataset, call.authorization, &routed);
        !status.ok()) {
      call.finish(status);
      return;
    }
    route(*routed);
  });
}

void ShardRouter::Locate(const v1::LocateRequest* request,
                         v1::LocateResponse* response, Call call) {
  // Routing one point is a table lookup: short enough for this thread;
  // transforming it (PROJ, perhaps making a transformer) is not.
  WithTopology(request->dataset(), /*here=*/request->crs().empty(), call,
               [=, this](const ShardTopology::Routed& routed) {
                 ForwardLocate(request, response, call, routed);
               });
}

void ShardRouter::ForwardLocate(const v1::LocateRequest* request,
                                v1::LocateResponse* response, const Call& call,
                                const ShardTopology::Routed& routed) {
  // Without a point the first shard says what is wrong.
  uint32_t shard = 0;
  if (request->has_point()) {
    const Point2 p{request->point().x(), request->point().y()};
    Point2 at = p;
    if (!request->crs().empty()) {
      if (Status status = gis::RequestPointsToDataset(
              request->crs(), routed.map.crs(), {&at, 1});
          !status.ok()) {
        call.finish(ToGrpcStatus(status));
        return;
      }
    }
    shard = routed.map.ShardOf(at);
    if (shard == ShardMap::kNoShard) {
      call.finish(ToGrpcStatus(
          NoShardFor(routed.map.dataset(), 0, p, routed.map.TileOf(at))));
      return;
    }
  }
  auto done = [this, shard, finish = call.finish,
               dataset = request->dataset()](grpc::Status status) {
    // The shard no longer serves that tile: learn the topology anew.
    if (status.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
      topology_->Forget(dataset);
    }
    finish(FromShard(*topology_, shard, status));
  };
  if (call.send_locate) {
    call.send_locate(shard, request, response, std::move(done));
    return;
  }
  std::shared_ptr<grpc::ClientContext> context = call.new_context();
  topology_->async(shard)->Locate(
      context.get(), request, response,
      [context, done = std::move(done)](grpc::Status status) {
        done(std::move(status));
      });
}

void ShardRouter::LocateBatch(const v1::LocateBatchRequest* request,
                              v1::LocateBatchResponse* response, Call call) {
  // A small batch is split on this thread as a point is routed; a large
  // one, or one to transform, on the pool.
  WithTopology(
      request->dataset(),
      request->xs_size() <= kInlineBatchPoints && request->crs().empty(), call,
      [=, this](const ShardTopology::Routed& routed) {
        RouteBatch(request, response, call, routed);
      });
}

void ShardRouter::RouteBatch(const v1::LocateBatchRequest* request,
                             v1::LocateBatchResponse* response,
                             const Call& call,
                             const ShardTopology::Routed& routed) {
  // Checked whole, so that an error names the point's index in the batch
  // (a shard's would name it in its part).
  if (Status valid = ValidateBatchRequest(*request, max_batch_points_);
      !valid.ok()) {
    call.finish(ToGrpcStatus(valid));
    return;
  }
  std::vector<Point2> where;
  if (!request->crs().empty()) {
    for (int i = 0; i < request->xs_size(); ++i) {
      where.push_back({request->xs(i), request->ys(i)});
    }
    if (Status status = gis::RequestPointsToDataset(request->crs(),
                                                    routed.map.crs(), where);
        !status.ok()) {
      call.finish(ToGrpcStatus(status));
      return;
    }
  }
  BatchSplit split;
  if (Status status = SplitBatch(*request, routed.map, &split, where);
      !status.ok()) {
    call.finish(ToGrpcStatus(status));
    return;
  }
  ShardCalls calls;
  calls.new_context = call.new_context;
  calls.start = [this, dataset = request->dataset()](
                    size_t shard, grpc::ClientContext* context,
                    v1::LocateBatchRequest* part,
                    v1::LocateBatchResponse* answer, ShardCalls::Done done) {
    topology_->async(shard)->LocateBatch(
        context, part, answer,
        [this, dataset, done = std::move(done)](grpc::Status status) {
          // The shard no longer serves those tiles: learn the topology anew.
          if (status.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
            topology_->Forget(dataset);
          }
          done(std::move(status));
        });
  };
  calls.target = [this](size_t shard) { return topology_->target(shard); };
  calls.run_merge = [this, large = request->xs_size() > kInlineBatchPoints](
                        std::function<void()> merge) {
    if (large) {
      pool_.Submit(std::move(merge));
    } else {
      merge();
    }
  };
  FanOutBatch(request, std::move(split), response, std::move(calls),
              call.finish);
}

void ShardRouter::Profile(const v1::ProfileRequest* request,
                          v1::ProfileResponse* response, Call call) {
  // The first vertex's shard, when its coordinates are the dataset's.
  const size_t shard =
      request->crs().empty() && request->vertices_size() > 0
          ? ShardNear(request->dataset(),
                      {request->vertices(0).x(), request->vertices(0).y()})
          : 0;
  ForwardWhole(shard, call, [&](auto* async, auto* context, auto done) {
    async->Profile(context, request, response, std::move(done));
  });
}

void ShardRouter::GridWhole(const v1::GridRequest* request,
                            v1::GridResponse* whole, Call call) {
  GridCollector::Start(topology_, ShardOfGrid(*request), call.new_context(),
                       request, max_whole_grid_cells_, whole, call.finish);
}

size_t ShardRouter::ShardOfGrid(const v1::GridRequest& request) const {
  // Halves first: the box may span the doubles.
  const v1::BoundingBox& box = request.box();
  return ShardNear(request.dataset(), {box.min_x() / 2 + box.max_x() / 2,
                                       box.min_y() / 2 + box.max_y() / 2});
}

size_t ShardRouter::ShardNear(const std::string& dataset,
                              const Point2& p) const {
  const std::shared_ptr<const ShardTopology::Routed> routed =
      topology_->Known(dataset);
  if (routed == nullptr) return 0;
  const uint32_t owner = routed->map.ShardOf(p);
  return owner == ShardMap::kNoShard ? 0 : owner;
}

void ShardRouter::GetTopology(const v1::GetTopologyRequest* request,
                              v1::GetTopologyResponse* response, Call call) {
  WithTopology(
      request->dataset(), /*here=*/true, call,
      [response, finish = call.finish](const ShardTopology::Routed& routed) {
        *response = routed.topology;
        finish(grpc::Status::OK);
      });
}

}  // namespace locator
