// ShardStreams: the shards' side of one LocateStream through the router:
// a LocateStream to each shard the client's points go to, opened at its
// first point, so that a point costs the router one message on a stream
// rather than a call of its own. Each shard stream carries its points in
// the order they were sent and answers them in that order (a shard answers
// its stream's points in order), so each answer is matched to its point by
// its place in the stream. A shard stream that ends (a point the shard
// refused, its deadline, a broken connection) fails every point it had not
// answered with its status; INTERNAL if it ended OK with points unanswered.
//
// The shard streams outlive the ShardStreams that opened them until their
// calls end: its destruction half-closes every stream once its points are
// written (every point sent must have been answered by then, as the
// router's LocateStreamReactor waits for its answers).
//
// Thread-safety: Send() may be called from any thread, one call at a time
// or concurrently; answers come on gRPC's threads.

#ifndef LOCATOR_SERVER_ROUTE_SHARD_STREAMS_H_
#define LOCATOR_SERVER_ROUTE_SHARD_STREAMS_H_

#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "common/mutex.h"
#include "locator/v1/locator.pb.h"
#include "server/route/shard_topology.h"

namespace locator {

class ShardStream;

class ShardStreams {
 public:
  // Runs once with the shard's status for the point: OK once its answer is
  // in the response Send() was given.
  using Done = std::function<void(grpc::Status status)>;

  // Streams to the shards of `topology` (which must outlive the streams'
  // calls), shard s's under contexts[s] (one per shard: they are made
  // while the client's call is surely alive, and used at a stream's first
  // point, perhaps after that call has ended).
  ShardStreams(ShardTopology* topology,
               std::vector<std::shared_ptr<grpc::ClientContext>> contexts);
  // Half-closes every shard stream once its points are written.
  ~ShardStreams();

  ShardStreams(const ShardStreams&) = delete;
  ShardStreams& operator=(const ShardStreams&) = delete;

  // Sends `request` on shard `shard`'s stream (opened now if it is not);
  // its answer goes to *response, which must live until `done` ran.
  void Send(size_t shard, const v1::LocateRequest& request,
            v1::LocateResponse* response, Done done) EXCLUDES(mu_);

 private:
  ShardTopology* const topology_;
  Mutex mu_;
  // Indexed by shard; each moves to its stream at its first point.
  std::vector<std::shared_ptr<grpc::ClientContext>> contexts_ GUARDED_BY(mu_);
  // Indexed by shard; null until its first point.
  std::vector<std::shared_ptr<ShardStream>> streams_ GUARDED_BY(mu_);
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_SHARD_STREAMS_H_
