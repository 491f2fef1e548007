// GridRelay: a Grid call that the router (locatord --route) forwards to one
// shard, streaming the shard's messages back as they come. Every shard maps
// the whole mesh of a tile set and answers a grid whole, so one shard is
// asked: the one holding the grid's centre.
//
// It is both reactors: the caller's stream (ServerWriteReactor) and the
// shard's (ClientReadReactor), with one message in flight: a message read
// from the shard is written to the caller, and the next is read only once
// that write is done, so a slow caller slows the shard's stream (gRPC's
// flow control) instead of filling the router's memory. The shard's status
// ends the caller's call, its message naming the shard, once no write to
// the caller is in flight; a caller that goes away cancels the shard's
// call.
//
// Thread-safety: gRPC runs each side's reactions one at a time, the two
// sides concurrently; what both read is guarded by mu_. The object deletes
// itself once both sides are done.

#ifndef LOCATOR_SERVER_ROUTE_GRID_RELAY_H_
#define LOCATOR_SERVER_ROUTE_GRID_RELAY_H_

#include <grpcpp/grpcpp.h>

#include <atomic>
#include <memory>
#include <optional>

#include "common/mutex.h"
#include "locator/v1/locator.grpc.pb.h"
#include "server/route/shard_topology.h"

namespace locator {

class GridRelay final : public grpc::ServerWriteReactor<v1::GridResponse>,
                        public grpc::ClientReadReactor<v1::GridResponse> {
 public:
  // Starts forwarding `request` to shard `shard` of `topology` (which must
  // outlive the call) on `shard_context` (the caller's deadline, metadata
  // and cancellation).
  GridRelay(const ShardTopology* topology, size_t shard,
            std::shared_ptr<grpc::ClientContext> shard_context,
            const v1::GridRequest& request);

  // The shard's side.
  void OnReadDone(bool ok) override;
  void OnDone(const grpc::Status& status) override;
  // The caller's side.
  void OnWriteDone(bool ok) override;
  void OnDone() override;

 private:
  // Deletes this when both sides are done.
  void SideDone();

  const ShardTopology* const topology_;
  const size_t shard_;
  const std::shared_ptr<grpc::ClientContext> shard_context_;
  const v1::GridRequest request_;
  v1::GridResponse message_;  // read from the shard, then written on
  Mutex mu_;
  bool writing_ GUARDED_BY(mu_) = false;  // a write to the caller in flight
  // The shard's status, kept while writing_ (Finish must wait for it).
  std::optional<grpc::Status> shard_status_ GUARDED_BY(mu_);
  std::atomic<int> sides_done_{0};
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_GRID_RELAY_H_
