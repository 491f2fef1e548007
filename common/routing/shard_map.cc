#include "common/routing/shard_map.h"

#include <utility>

#include "common/input_text.h"

namespace locator {

StatusOr<ShardMap> ShardMap::FromTopology(
    const v1::GetTopologyResponse& topology) {
  ShardMap map;
  map.dataset_ = topology.dataset();
  map.crs_ = topology.crs();
  if (topology.shards_size() == 0) {
    return Status::InvalidArgument("topology of dataset '" + map.dataset_ +
                                   "' lists no shard");
  }
  for (const v1::TopologyShard& shard : topology.shards()) {
    map.targets_.push_back(shard.target());
  }
  if (!topology.tiled()) {
    if (topology.shards_size() != 1) {
      return Status::InvalidArgument(
          "topology of dataset '" + map.dataset_ +
          "' is not tiled but lists more than one shard");
    }
    map.shard_of_tile_ = {0};
    map.complete_ = true;
    return map;
  }
  if (topology.grid_level() > TileRouter::kMaxLevel) {
    return Status::InvalidArgument("topology of dataset '" + map.dataset_ +
                                   "': grid level above " +
                                   std::to_string(TileRouter::kMaxLevel));
  }
  std::vector<uint32_t> first_cells;
  first_cells.reserve(topology.tiles_size());
  for (int t = 0; t < topology.tiles_size(); ++t) {
    const v1::TopologyTile& tile = topology.tiles(t);
    const uint64_t next_first = t + 1 < topology.tiles_size()
                                    ? topology.tiles(t + 1).first_cell()
                                    : uint64_t{1}
                                          << (2 * topology.grid_level());
    if (tile.end_cell() != next_first || tile.end_cell() <= tile.first_cell()) {
      return Status::InvalidArgument(
          "topology of dataset '" + map.dataset_ + "': tile " +
          std::to_string(t) + " does not end where the next tile starts");
    }
    first_cells.push_back(tile.first_cell());
  }
  const v1::BoundingBox& b = topology.bounds();
  BoundingBox box{b.min_x(), b.min_y(), b.max_x(), b.max_y()};
  StatusOr<TileRouter> tiles = TileRouter::Create(
      box, static_cast<int>(topology.grid_level()), std::move(first_cells));
  if (!tiles.ok()) {
    return Status::InvalidArgument("topology of dataset '" + map.dataset_ +
                                   "': " + tiles.status().message());
  }
  map.tiles_ = *std::move(tiles);
  map.shard_of_tile_.assign(map.tiles_->num_tiles(), kNoShard);
  for (int s = 0; s < topology.shards_size(); ++s) {
    for (const uint32_t tile : topology.shards(s).tiles()) {
      if (tile >= map.shard_of_tile_.size() ||
          map.shard_of_tile_[tile] != kNoShard) {
        return Status::InvalidArgument(
            "topology of dataset '" + map.dataset_ + "': shard " +
            std::to_string(s) + " lists tile " + std::to_string(tile) +
            (tile >= map.shard_of_tile_.size() ? ", which does not exist"
                                               : ", which another lists"));
      }
      map.shard_of_tile_[tile] = static_cast<uint32_t>(s);
    }
  }
  map.complete_ = true;
  for (const uint32_t shard : map.shard_of_tile_) {
    if (shard == kNoShard) map.complete_ = false;
  }
  return map;
}

size_t ShardMap::TileOf(const Point2& p) const {
  return tiles_ ? tiles_->TileOf(p) : 0;
}

uint32_t ShardMap::ShardOf(const Point2& p) const {
  return shard_of_tile_[TileOf(p)];
}

Status NoShardFor(const std::string& dataset, size_t index, const Point2& p,
                  size_t tile) {
  return Status::FailedPrecondition(
      "point " + std::to_string(index) + " " + PointText(p) + " lies in tile " +
      std::to_string(tile) + " of dataset '" + dataset +
      "', which no shard in its topology serves; route through a router "
      "(locatord --route) or a complete topology");
}

}  // namespace locator
