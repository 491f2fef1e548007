#include "server/route/shard_router.h"

#include <utility>
#include <vector>

#include "common/mutex.h"
#include "common/routing/batch_split.h"
#include "server/app/batch_locator.h"
#include "server/grpc/status_mapping.h"

namespace locator {
namespace {

// Batches up to this many points are split and merged on the calling
// thread (as short as routing one point); larger ones on the pool.
constexpr int kInlineBatchPoints = 4096;

grpc::Status CannotRouteCrs() {
  return grpc::Status(
      grpc::StatusCode::INVALID_ARGUMENT,
      "the router routes points in the dataset's own coordinates; a request "
      "with a crs must go to a shard or an unsharded server");
}

// The state of one routed LocateBatch: the parts, the shards' answers, and
// what is left to wait for. Lives until the last answer has been merged.
struct BatchFanOut {
  BatchSplit split;
  std::vector<v1::LocateBatchResponse> answers;
  std::vector<std::shared_ptr<grpc::ClientContext>> contexts;
  Mutex mu;
  size_t pending GUARDED_BY(mu) = 0;
  grpc::Status failure GUARDED_BY(mu);
};

}  // namespace

grpc::Status FromShard(const ShardTopology& topology, size_t shard,
                       const grpc::Status& status) {
  if (status.ok()) return status;
  return grpc::Status(status.error_code(), "shard " + std::to_string(shard) +
                                               " (" + topology.target(shard) +
                                               "): " + status.error_message());
}

ShardRouter::ShardRouter(ShardTopology* topology, size_t threads,
                         size_t max_batch_points)
    : topology_(topology),
      max_batch_points_(max_batch_points),
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
  // Routing one point is a table lookup: short enough for this thread.
  WithTopology(request->dataset(), /*here=*/true, call,
               [=, this](const ShardTopology::Routed& routed) {
                 ForwardLocate(request, response, call, routed);
               });
}

void ShardRouter::ForwardLocate(const v1::LocateRequest* request,
                                v1::LocateResponse* response, const Call& call,
                                const ShardTopology::Routed& routed) {
  if (!request->crs().empty()) {
    call.finish(CannotRouteCrs());
    return;
  }
  // Without a point the first shard says what is wrong.
  uint32_t shard = 0;
  if (request->has_point()) {
    const Point2 p{request->point().x(), request->point().y()};
    shard = routed.map.ShardOf(p);
    if (shard == ShardMap::kNoShard) {
      call.finish(ToGrpcStatus(
          NoShardFor(routed.map.dataset(), 0, p, routed.map.TileOf(p))));
      return;
    }
  }
  std::shared_ptr<grpc::ClientContext> context = call.new_context();
  topology_->async(shard)->Locate(
      context.get(), request, response,
      [this, context, shard, finish = call.finish,
       dataset = request->dataset()](grpc::Status status) {
        if (status.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
          topology_->Forget(dataset);
        }
        finish(FromShard(*topology_, shard, status));
      });
}

void ShardRouter::LocateBatch(const v1::LocateBatchRequest* request,
                              v1::LocateBatchResponse* response, Call call) {
  // A small batch is split on this thread as a point is routed; a large
  // one on the pool.
  WithTopology(request->dataset(), request->xs_size() <= kInlineBatchPoints,
               call, [=, this](const ShardTopology::Routed& routed) {
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
  if (!request->crs().empty()) {
    call.finish(CannotRouteCrs());
    return;
  }
  auto fan = std::make_shared<BatchFanOut>();
  if (Status split = SplitBatch(*request, routed.map, &fan->split);
      !split.ok()) {
    call.finish(ToGrpcStatus(split));
    return;
  }
  const size_t shards = fan->split.parts.size();
  fan->answers.resize(shards);
  fan->contexts.resize(shards);
  std::vector<size_t> called;
  for (size_t s = 0; s < shards; ++s) {
    if (!fan->split.positions[s].empty()) called.push_back(s);
  }
  const auto merge = [fan, request, response, finish = call.finish] {
    grpc::Status failure;
    {
      MutexLock lock(&fan->mu);
      failure = fan->failure;
    }
    if (!failure.ok()) {
      finish(failure);
      return;
    }
    finish(
        ToGrpcStatus(MergeBatch(*request, fan->split, fan->answers, response)));
  };
  if (called.empty()) {  // an empty batch
    merge();
    return;
  }
  {
    MutexLock lock(&fan->mu);
    fan->pending = called.size();
  }
  // Every context exists before the first call starts: a failing part
  // cancels the others'.
  for (const size_t s : called) fan->contexts[s] = call.new_context();
  for (const size_t s : called) {
    topology_->async(s)->LocateBatch(
        fan->contexts[s].get(), &fan->split.parts[s], &fan->answers[s],
        [this, fan, s, merge, request,
         dataset = request->dataset()](grpc::Status status) {
          if (status.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
            topology_->Forget(dataset);
          }
          bool first_failure = false, last = false;
          {
            MutexLock lock(&fan->mu);
            first_failure = !status.ok() && fan->failure.ok();
            if (first_failure) fan->failure = FromShard(*topology_, s, status);
            last = --fan->pending == 0;
          }
          if (first_failure && !last) {
            // The other parts are of no use any more (cancelled unlocked: a
            // cancellation may run their callbacks at once).
            for (const auto& other : fan->contexts) {
              if (other != nullptr && other != fan->contexts[s]) {
                other->TryCancel();
              }
            }
          }
          if (!last) return;
          if (request->xs_size() <= kInlineBatchPoints) {
            merge();
          } else {
            pool_.Submit(merge);
          }
        });
  }
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
