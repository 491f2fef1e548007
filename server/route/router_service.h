// RouterService: locator.v1.Locator as a stateless router (locatord
// --route) in front of the shards of tiled datasets, for clients that
// cannot route by GetTopology themselves (browsers behind a gateway, curl,
// grpcurl). It scales like any replica: behind nginx, several routers share
// nothing but the shards.
//
//   Locate        to the shard serving the point's tile
//   LocateBatch   split by shard, the parts sent at once, the answers
//                 merged in input order (common/routing/batch_split.h)
//   GetTopology   every shard with its target and tiles (complete when
//                 every tile has one)
//   Profile       to the shard of the line's first vertex (any shard
//                 answers a profile whole)
//   GetStats, ListDatasets   to the first shard
//   LocateStream, Grid, Retune, Reload   UNIMPLEMENTED: call the shards
//
// Points are routed in the dataset's coordinates: a Locate or LocateBatch
// with a crs is INVALID_ARGUMENT. A shard's error reaches the client with
// its code, the message naming the shard; a shard refusing a point it does
// not serve also makes the router fetch the topology again.
//
// Every forwarded call carries the caller's deadline (or the router's
// default) and authorization header, and is cancelled with the caller's.
// Topology fetches, which wait on the shards, and the splitting and merging
// of large batches run on the router's worker pool, never on a gRPC
// callback thread; routing a point or a small batch by a known topology is
// as short as a reaction should be and runs there.
//
// Thread-safety: gRPC calls its methods concurrently.

#ifndef LOCATOR_SERVER_ROUTE_ROUTER_SERVICE_H_
#define LOCATOR_SERVER_ROUTE_ROUTER_SERVICE_H_

#include <chrono>
#include <memory>
#include <string>

#include "locator/v1/locator.grpc.pb.h"
#include "server/route/shard_topology.h"
#include "server/serving/worker_pool.h"

namespace locator {

class RouterService final : public v1::Locator::CallbackService {
 public:
  // Routes to the shards of `topology` (which must outlive it), with
  // `threads` workers, giving calls without a deadline `default_deadline`
  // and refusing batches of more than `max_batch_points` points as a
  // server does (ValidateBatchRequest, before any shard is called).
  RouterService(ShardTopology* topology, size_t threads,
                std::chrono::milliseconds default_deadline,
                size_t max_batch_points);

  grpc::ServerUnaryReactor* Locate(grpc::CallbackServerContext* context,
                                   const v1::LocateRequest* request,
                                   v1::LocateResponse* response) override;
  grpc::ServerUnaryReactor* LocateBatch(
      grpc::CallbackServerContext* context,
      const v1::LocateBatchRequest* request,
      v1::LocateBatchResponse* response) override;
  grpc::ServerUnaryReactor* GetTopology(
      grpc::CallbackServerContext* context,
      const v1::GetTopologyRequest* request,
      v1::GetTopologyResponse* response) override;
  grpc::ServerUnaryReactor* Profile(grpc::CallbackServerContext* context,
                                    const v1::ProfileRequest* request,
                                    v1::ProfileResponse* response) override;
  grpc::ServerUnaryReactor* GetStats(grpc::CallbackServerContext* context,
                                     const v1::GetStatsRequest* request,
                                     v1::GetStatsResponse* response) override;
  grpc::ServerUnaryReactor* ListDatasets(
      grpc::CallbackServerContext* context,
      const v1::ListDatasetsRequest* request,
      v1::ListDatasetsResponse* response) override;
  grpc::ServerUnaryReactor* Retune(grpc::CallbackServerContext* context,
                                   const v1::RetuneRequest* request,
                                   v1::RetuneResponse* response) override;
  grpc::ServerUnaryReactor* Reload(grpc::CallbackServerContext* context,
                                   const v1::ReloadRequest* request,
                                   v1::ReloadResponse* response) override;
  grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse>* LocateStream(
      grpc::CallbackServerContext* context) override;
  grpc::ServerWriteReactor<v1::GridResponse>* Grid(
      grpc::CallbackServerContext* context,
      const v1::GridRequest* request) override;

 private:
  // A context for a call to a shard on behalf of `context`'s caller.
  std::shared_ptr<grpc::ClientContext> ShardContext(
      const grpc::CallbackServerContext& context) const;
  // Runs `route` with `dataset`'s topology: at once on this thread when it
  // is known and `here`, else on the pool once known (a failed fetch
  // finishes `reactor` with the shards' error).
  template <typename Route>
  void WithTopology(grpc::CallbackServerContext* context,
                    const std::string& dataset, bool here,
                    grpc::ServerUnaryReactor* reactor, Route route);
  // Sends a Locate to the shard of its point by `routed`; `reactor`
  // finishes with the shard's answer.
  void ForwardLocate(grpc::CallbackServerContext* context,
                     const v1::LocateRequest* request,
                     v1::LocateResponse* response,
                     grpc::ServerUnaryReactor* reactor,
                     const ShardTopology::Routed& routed);
  // Splits a LocateBatch by `routed`, sends the parts and finishes
  // `reactor` with the merged answers.
  void RouteBatch(grpc::CallbackServerContext* context,
                  const v1::LocateBatchRequest* request,
                  v1::LocateBatchResponse* response,
                  grpc::ServerUnaryReactor* reactor,
                  const ShardTopology::Routed& routed);

  ShardTopology* const topology_;
  const std::chrono::milliseconds default_deadline_;
  const size_t max_batch_points_;
  WorkerPool pool_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_ROUTER_SERVICE_H_
