// ShardMap: a dataset's GetTopology answer as routing uses it: which shard
// serves each point, and each shard's gRPC target. Clients (the CLI,
// locator-load, the C++ client library) and the router (locatord --route)
// build one from a GetTopologyResponse and split batches by it
// (batch_split.h).
//
// Thread-safety: immutable after construction; any thread may call it.

#ifndef LOCATOR_COMMON_ROUTING_SHARD_MAP_H_
#define LOCATOR_COMMON_ROUTING_SHARD_MAP_H_

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/routing/tile_router.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "locator/v1/locator.pb.h"

namespace locator {

class ShardMap {
 public:
  static constexpr uint32_t kNoShard = 0xffffffffu;

  // The map of `topology`. InvalidArgument naming what is wrong when it is
  // not a well-formed topology (tiles not contiguous from cell 0, a shard
  // listing a tile that does not exist or that another shard lists, no
  // shard at all). A tile no shard serves is allowed (ShardOf() answers
  // kNoShard for its points; complete() is false).
  static StatusOr<ShardMap> FromTopology(
      const v1::GetTopologyResponse& topology);

  // The shard serving p, or kNoShard.
  uint32_t ShardOf(const Point2& p) const;
  // The tile p falls in (0 for a dataset that is not tiled).
  size_t TileOf(const Point2& p) const;

  size_t num_shards() const { return targets_.size(); }
  // Shard s's gRPC target; empty: the server that answered GetTopology.
  const std::string& target(size_t shard) const { return targets_[shard]; }
  // Whether every tile has a shard.
  bool complete() const { return complete_; }
  // Whether points go to more than one shard.
  bool sharded() const { return targets_.size() > 1; }
  const std::string& dataset() const { return dataset_; }
  // The dataset's CRS (GetTopologyResponse.crs), in which points are
  // routed; empty when it has none.
  const std::string& crs() const { return crs_; }
  // The tiles, when the dataset is a tile set.
  const std::optional<TileRouter>& tiles() const { return tiles_; }

 private:
  ShardMap() = default;

  std::string dataset_;
  std::string crs_;
  std::optional<TileRouter> tiles_;
  std::vector<uint32_t> shard_of_tile_;
  std::vector<std::string> targets_;
  bool complete_ = false;
};

// FailedPrecondition saying that point `index` (p), in tile `tile`, has no
// shard in the topology of `dataset`: one wording for the clients and the
// router.
Status NoShardFor(const std::string& dataset, size_t index, const Point2& p,
                  size_t tile);

}  // namespace locator

#endif  // LOCATOR_COMMON_ROUTING_SHARD_MAP_H_
