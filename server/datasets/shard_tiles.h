// ShardTiles: the tiles of a tile set one server serves: all of them, or
// those `locatord --tiles SELECTOR` selects. A shard answers only the
// points of its own tiles, FAILED_PRECONDITION otherwise, so that a client
// routing by a stale or wrong topology learns it at once instead of
// getting a slow answer from cold pages; GetTopology reports the tiles.
// Profiles, grids and terrain tiles cross tile boundaries and are answered
// whole by any shard (every shard maps the whole mesh; the page cache keeps
// what is used).
//
// Thread-safety: immutable after construction; any thread may call it.

#ifndef LOCATOR_SERVER_DATASETS_SHARD_TILES_H_
#define LOCATOR_SERVER_DATASETS_SHARD_TILES_H_

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/routing/tile_router.h"
#include "locator/geometry.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator {

class ShardTiles {
 public:
  // The tiles of `router` that `selector` names ("": all of them):
  //   K/N        the K-th (from 0) of N contiguous parts of the tiles, each
  //              of about the same number of tiles;
  //   A-B,C,...  tiles and inclusive ranges of tiles, by index.
  // InvalidArgument quoting the selector when it is malformed, names a tile
  // the set does not have, or selects none.
  static StatusOr<std::shared_ptr<const ShardTiles>> Select(
      TileRouter router, std::string_view selector, uint64_t fingerprint);
  // Whether `selector` is well formed, whatever the tile set (for
  // locatord's flags, before any tile set is read).
  [[nodiscard]] static Status CheckSelector(std::string_view selector);

  // OK when every point is in a served tile; FailedPrecondition naming the
  // first that is not (its index counted from `first_index`) and its tile.
  [[nodiscard]] Status CheckServed(std::span<const Point2> points,
                                   size_t first_index) const;

  const TileRouter& router() const { return router_; }
  // The served tiles, ascending.
  const std::vector<uint32_t>& served() const { return served_; }
  bool serves_all() const { return served_.size() == router_.num_tiles(); }
  // The tile set's source fingerprint.
  uint64_t fingerprint() const { return fingerprint_; }

 private:
  ShardTiles(TileRouter router, std::vector<uint32_t> served,
             std::string selector, uint64_t fingerprint);

  const TileRouter router_;
  const std::vector<uint32_t> served_;
  std::vector<bool> is_served_;  // by tile
  const std::string selector_;
  const uint64_t fingerprint_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_DATASETS_SHARD_TILES_H_
