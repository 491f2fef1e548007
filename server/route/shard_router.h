// ShardRouter: what a router (locatord --route) does with a call, whatever
// transport brought it: Locate to the shard of its point, LocateBatch split
// by shard and merged in input order (common/routing/batch_split.h),
// Profile to the shard of its first vertex, a grid read whole from the shard
// of its centre (for an answer in one message), and GetTopology from the
// shards' (ShardTopology). The gRPC service
// (router_service.h) and the HTTP/JSON API (router_http_api.h) are thin
// adapters over it.
//
// Points are routed where they are in the dataset's CRS: a request with a
// crs has its points transformed as a shard transforms them
// (gis::RequestTransformer, to GetTopologyResponse.crs), with a shard's
// errors, and is sent on with its points as they came. A batch is
// validated whole first (the point limit, finite coordinates:
// ValidateBatchRequest), so that an error names the point's index in the
// batch. A shard's error reaches the caller with its
// code, the message naming the shard; a shard refusing a point it does not
// serve also makes the router fetch the topology again.
//
// Topology fetches, which wait on the shards, transforms, and the splitting
// and merging of large batches run on the router's worker pool; routing a
// point or a small batch in the dataset's CRS by a known topology runs on
// the calling thread (as short as a gRPC reaction should be).
//
// Thread-safety: all methods may be called concurrently.

#ifndef LOCATOR_SERVER_ROUTE_SHARD_ROUTER_H_
#define LOCATOR_SERVER_ROUTE_SHARD_ROUTER_H_

#include <grpcpp/grpcpp.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "locator/v1/locator.grpc.pb.h"
#include "server/route/shard_topology.h"
#include "server/serving/worker_pool.h"

namespace locator {

// `status` from shard `shard` of `topology`, its message naming the shard.
grpc::Status FromShard(const ShardTopology& topology, size_t shard,
                       const grpc::Status& status);

class ShardRouter {
 public:
  // One call, as its transport hands it over.
  struct Call {
    // The caller's authorization header, sent on to the shards.
    std::optional<std::string> authorization;
    // Makes the context of a call to a shard (deadline, metadata).
    std::function<std::shared_ptr<grpc::ClientContext>()> new_context;
    // Ends the call with its outcome; the response is complete when OK.
    std::function<void(grpc::Status)> finish;
    // How a Locate reaches its shard when set (a stream's points, on
    // streams to the shards: ShardStreams): sends `request` to `shard`,
    // its answer into *response, and runs `done` with the shard's status.
    // Unset: a unary Locate under a context from new_context.
    std::function<void(size_t shard, const v1::LocateRequest* request,
                       v1::LocateResponse* response,
                       std::function<void(grpc::Status)> done)>
        send_locate = nullptr;
  };

  // Routes to the shards of `topology` (which must outlive it) with
  // `threads` workers, refusing batches of more than `max_batch_points` and
  // grids in one message (GridWhole) of more than `max_whole_grid_cells`.
  ShardRouter(ShardTopology* topology, size_t threads, size_t max_batch_points,
              uint64_t max_whole_grid_cells);

  // The calls; `request` and `response` must live until call.finish ran.
  // Locate makes at most one shard call (call.new_context runs at most
  // once), perhaps on another thread once the topology is known.
  void Locate(const v1::LocateRequest* request, v1::LocateResponse* response,
              Call call);
  void LocateBatch(const v1::LocateBatchRequest* request,
                   v1::LocateBatchResponse* response, Call call);
  void GetTopology(const v1::GetTopologyRequest* request,
                   v1::GetTopologyResponse* response, Call call);
  // To the shard of the line's first vertex (any shard answers a profile
  // whole: ShardNear).
  void Profile(const v1::ProfileRequest* request, v1::ProfileResponse* response,
               Call call);

  // To the shard of the grid's centre (ShardOfGrid), read whole into one
  // message (GridCollector): a grid of more than max_whole_grid_cells is
  // RESOURCE_EXHAUSTED.
  void GridWhole(const v1::GridRequest* request, v1::GridResponse* whole,
                 Call call);
  // The shard whose pages `request`'s grid touches: ShardNear its centre.
  size_t ShardOfGrid(const v1::GridRequest& request) const;

  // The shard whose pages a profile or grid about `p` in `dataset`'s
  // coordinates touches: the one serving p; 0 (any shard answers those
  // whole) while the topology is not known or when no shard serves p.
  size_t ShardNear(const std::string& dataset, const Point2& p) const;

  ShardTopology& topology() const { return *topology_; }

  // Forwards a call whole to shard `shard`: `start(async, context, done)`
  // starts the stub's callback method (async: the shard's
  // async_interface) under a context from call.new_context, and
  // call.finish gets its status, the message naming the shard.
  template <typename Start>
  void ForwardWhole(size_t shard, const Call& call, Start start) {
    std::shared_ptr<grpc::ClientContext> context = call.new_context();
    start(topology_->async(shard), context.get(),
          [this, context, shard, finish = call.finish](grpc::Status status) {
            finish(FromShard(*topology_, shard, status));
          });
  }

 private:
  // Runs `route` with `dataset`'s topology: at once on this thread when it
  // is known and `here`, else on the pool once known (a failed fetch ends
  // the call with the shards' error).
  void WithTopology(
      const std::string& dataset, bool here, const Call& call,
      std::function<void(const ShardTopology::Routed& routed)> route);
  void ForwardLocate(const v1::LocateRequest* request,
                     v1::LocateResponse* response, const Call& call,
                     const ShardTopology::Routed& routed);
  void RouteBatch(const v1::LocateBatchRequest* request,
                  v1::LocateBatchResponse* response, const Call& call,
                  const ShardTopology::Routed& routed);

  ShardTopology* const topology_;
  const size_t max_batch_points_;
  const uint64_t max_whole_grid_cells_;
  WorkerPool pool_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_SHARD_ROUTER_H_
