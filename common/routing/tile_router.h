// TileRouter: which tile of a tile set a point falls in, by the rule the set
// was cut by (server/core/tiling/cells/cell_grid.h): the point's HilbertKey
// over the set's bounds, shifted down to the grid's level, is its cell, and
// a tile is a range of cells along the curve. Shards check it before they
// answer; clients and the router (locatord --route) split batches by it.
// Every point has a tile, also outside the bounds (the nearest border cell)
// and NaN (cell 0), so routing never fails on a coordinate.
//
// Thread-safety: immutable after construction; any thread may call it.

#ifndef LOCATOR_COMMON_ROUTING_TILE_ROUTER_H_
#define LOCATOR_COMMON_ROUTING_TILE_ROUTER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "locator/geometry.h"
#include "locator/status_or.h"

namespace locator {

class TileRouter {
 public:
  // The finest grid a tile set can have: a level below HilbertKey's 2^16 x
  // 2^16, so that every cell number and range end fits 32 bits.
  static constexpr int kMaxLevel = 15;

  // The router of tiles starting at `first_cells` on the grid of 2^level x
  // 2^level cells over `box`. InvalidArgument unless the box is finite and
  // not empty, 0 <= level <= kMaxLevel, and first_cells starts at 0 and
  // ascends strictly below 4^level.
  static StatusOr<TileRouter> Create(const BoundingBox& box, int level,
                                     std::vector<uint32_t> first_cells);

  // The index of the tile holding p.
  size_t TileOf(const Point2& p) const;
  // The cell p falls in, along the curve.
  uint32_t CellOf(const Point2& p) const;

  size_t num_tiles() const { return first_cells_.size(); }
  const BoundingBox& box() const { return box_; }
  int level() const { return level_; }
  // Cells along the curve: 4^level.
  uint64_t num_cells() const { return uint64_t{1} << (2 * level_); }
  // Tile t's cells are [first_cell(t), end_cell(t)).
  uint32_t first_cell(size_t tile) const { return first_cells_[tile]; }
  uint64_t end_cell(size_t tile) const {
    return tile + 1 < first_cells_.size() ? first_cells_[tile + 1]
                                          : num_cells();
  }

 private:
  TileRouter(const BoundingBox& box, int level,
             std::vector<uint32_t> first_cells)
      : box_(box), level_(level), first_cells_(std::move(first_cells)) {}

  BoundingBox box_;
  int level_;
  std::vector<uint32_t> first_cells_;
};

}  // namespace locator

#endif  // LOCATOR_COMMON_ROUTING_TILE_ROUTER_H_
