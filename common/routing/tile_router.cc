#include "common/routing/tile_router.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "common/hilbert.h"

namespace locator {

StatusOr<TileRouter> TileRouter::Create(const BoundingBox& box, int level,
                                        std::vector<uint32_t> first_cells) {
  if (!std::isfinite(box.min_x) || !std::isfinite(box.min_y) ||
      !std::isfinite(box.max_x) || !std::isfinite(box.max_y) || box.empty()) {
    return Status::InvalidArgument(
        "tile bounds must be finite with min <= max");
  }
  if (level < 0 || level > kMaxLevel) {
    return Status::InvalidArgument("grid level " + std::to_string(level) +
                                   " is outside 0.." +
                                   std::to_string(kMaxLevel));
  }
  const uint64_t cells = uint64_t{1} << (2 * level);
  if (first_cells.empty() || first_cells[0] != 0) {
    return Status::InvalidArgument("the first tile must start at cell 0");
  }
  for (size_t t = 1; t < first_cells.size(); ++t) {
    if (first_cells[t] <= first_cells[t - 1] || first_cells[t] >= cells) {
      return Status::InvalidArgument(
          "tile " + std::to_string(t) + " starts at cell " +
          std::to_string(first_cells[t]) +
          ": tiles must start at ascending cells below " +
          std::to_string(cells));
    }
  }
  return TileRouter(box, level, std::move(first_cells));
}

uint32_t TileRouter::CellOf(const Point2& p) const {
  return static_cast<uint32_t>(uint64_t{HilbertKey(p, box_)} >>
                               (2 * (16 - level_)));
}

size_t TileRouter::TileOf(const Point2& p) const {
  const uint32_t cell = CellOf(p);
  return static_cast<size_t>(
      std::upper_bound(first_cells_.begin(), first_cells_.end(), cell) -
      first_cells_.begin() - 1);
}

}  // namespace locator
