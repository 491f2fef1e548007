// ShardTopology: what a router (locatord --route) knows of its shards: a
// channel to each, and per dataset the topology their GetTopology answers
// add up to (each shard lists the tiles it serves; the router lists every
// shard with its target). Topologies are fetched on first use and kept
// until a shard refuses a point it was sent (Forget()): shards may be
// restarted with other tiles, and the router holds no other state.
//
// A dataset that is not a tile set is served whole by every shard that has
// it: the router sends all its points to the first shard.
//
// The contexts of the calls made on its channels come from NewContext(),
// counted, and it outlives them: see common/in_flight.h for why the last
// hold on a channel must not be let go on a gRPC thread.
//
// Thread-safety: all methods may be called concurrently. Get() blocks on
// the shards on a first use: call it off the gRPC callback threads.

#ifndef LOCATOR_SERVER_ROUTE_SHARD_TOPOLOGY_H_
#define LOCATOR_SERVER_ROUTE_SHARD_TOPOLOGY_H_

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/channel_options.h"
#include "common/in_flight.h"
#include "common/mutex.h"
#include "common/routing/shard_map.h"
#include "locator/v1/locator.grpc.pb.h"

namespace locator {

class ShardTopology {
 public:
  // A dataset's merged topology and the map routing by it.
  struct Routed {
    v1::GetTopologyResponse topology;
    ShardMap map;
  };

  // Shards at `targets` (one per shard), reached over channels made with
  // `channel` (its target ignored); a fetch waits at most `fetch_deadline`.
  ShardTopology(const std::vector<std::string>& targets,
                const ChannelOptions& channel,
                std::chrono::milliseconds fetch_deadline);
  // Waits until every context from NewContext() has been deleted.
  ~ShardTopology();

  ShardTopology(const ShardTopology&) = delete;
  ShardTopology& operator=(const ShardTopology&) = delete;

  // The routed topology of `dataset` ("": the shards' default) into
  // *routed, fetched with `authorization` (the caller's header, if any)
  // when not known. The first failing shard's status, its message naming
  // the shard; FAILED_PRECONDITION when their answers disagree (other tile
  // sets, a tile served twice).
  grpc::Status Get(const std::string& dataset,
                   const std::optional<std::string>& authorization,
                   std::shared_ptr<const Routed>* routed) EXCLUDES(mu_);
  // The routed topology of `dataset` if it is known; null otherwise. Never
  // blocks.
  std::shared_ptr<const Routed> Known(const std::string& dataset) const
      EXCLUDES(mu_);
  // Drops what is known of `dataset`: the next Get() fetches it again.
  void Forget(const std::string& dataset) EXCLUDES(mu_);

  size_t num_shards() const { return stubs_.size(); }
  const std::string& target(size_t shard) const { return targets_[shard]; }
  v1::Locator::StubInterface::async_interface* async(size_t shard) const {
    return stubs_[shard]->async();
  }
  // `context` (of a call to a shard), counted until it is deleted.
  std::shared_ptr<grpc::ClientContext> NewContext(
      std::unique_ptr<grpc::ClientContext> context) {
    return contexts_.Counted(std::move(context));
  }

 private:
  grpc::Status Fetch(const std::string& dataset,
                     const std::optional<std::string>& authorization,
                     std::shared_ptr<const Routed>* routed) const;

  const std::vector<std::string> targets_;
  std::vector<std::unique_ptr<v1::Locator::Stub>> stubs_;
  const std::chrono::milliseconds fetch_deadline_;
  mutable Mutex mu_;
  std::map<std::string, std::shared_ptr<const Routed>> known_ GUARDED_BY(mu_);
  InFlight contexts_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ROUTE_SHARD_TOPOLOGY_H_
