// RouterService: locator.v1.Locator as a stateless router (locatord
// --route) in front of the shards of tiled datasets, for clients that
// cannot route by GetTopology themselves (browsers behind a gateway, curl,
// grpcurl). It scales like any replica: behind nginx, several routers share
// nothing but the shards.
//
//   Locate, LocateBatch, GetTopology   ShardRouter (shard_router.h)
//   LocateStream  each point routed as a Locate and sent on a stream to
//                 its shard (ShardStreams), several in flight, answered
//                 in order (LocateStreamReactor)
//   Profile       to the shard of the line's first vertex (any shard
//                 answers a profile whole)
//   Grid          to the shard of the grid's centre, streamed back as it
//                 comes (GridRelay: any shard answers a grid whole)
//   GetStats, ListDatasets   to the first shard
//   Retune, Reload   UNIMPLEMENTED: call the shards
//
// Every forwarded call carries the caller's deadline (or the router's
// default) and authorization header, and is cancelled with the caller's.
//
// Thread-safety: gRPC calls its methods concurrently.

#ifndef LOCATOR_SERVER_ROUTE_ROUTER_SERVICE_H_
#define LOCATOR_SERVER_ROUTE_ROUTER_SERVICE_H_

#include <chrono>
#include <memory>
#include <string>

#include "locator/v1/locator.grpc.pb.h"
#include "server/route/shard_router.h"
#include "server/route/shard_topology.h"

namespace locator {

class RouterService final : public v1::Locator::CallbackService {
 public:
  // Routes with `router` (which must outlive it), giving calls without a
  // deadline `default_deadline`.
  RouterService(ShardRouter* router,
                std::chrono::milliseconds default_deadline);

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
  // A context for a call to a shard on behalf of `context`'s caller: its
  // deadline (or the default), cancellation and authorization.
  std::shared_ptr<grpc::ClientContext> ShardContext(
      const grpc::CallbackServerContext& context) const;
  // `context`'s call as the router takes it, finishing `reactor`.
  ShardRouter::Call CallOf(grpc::CallbackServerContext* context,
                           grpc::ServerUnaryReactor* reactor);

  ShardRouter* const router_;
  ShardTopology* const topology_;
  const std::chrono::milliseconds default_deadline_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_ROUTER_SERVICE_H_
