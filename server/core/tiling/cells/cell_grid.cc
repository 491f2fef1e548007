#include "server/core/tiling/cells/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace locator {

CellGrid::CellGrid(const BoundingBox& box, int level)
    : box_(box), level_(level), shift_(16 - level), side_(1u << level) {}

int CellGrid::LevelFor(size_t points, size_t per_cell) {
  int level = 0;
  while (level < kMaxLevel && (size_t{1} << (2 * level)) * per_cell < points) {
    ++level;
  }
  return level;
}

uint32_t CellGrid::Cell(uint32_t column, uint32_t row) const {
  // The curve at 2^16 refines the curve at this level: the fine cells of a
  // cell are consecutive, so the cell's number is any fine key's prefix.
  return CellOfKey(HilbertIndex(column << shift_, row << shift_));
}

void CellGrid::CellPosition(uint32_t cell, uint32_t* column,
                            uint32_t* row) const {
  // The inverse of HilbertIndex's walk, from the smallest quadrants up.
  uint32_t x = 0;
  uint32_t y = 0;
  for (uint32_t s = 1; s < side_; s <<= 1) {
    const uint32_t rx = 1 & (cell / 2);
    const uint32_t ry = 1 & (cell ^ rx);
    if (ry == 0) {
      if (rx == 1) {
        x = s - 1 - x;
        y = s - 1 - y;
      }
      std::swap(x, y);
    }
    x += s * rx;
    y += s * ry;
    cell /= 4;
  }
  *column = x;
  *row = y;
}

CellGrid::Interval CellGrid::RowSpan(uint32_t row) const {
  const double lo = box_.min_y;
  const double hi = box_.max_y;
  // The band's edges as weighted means (no overflow); HilbertCell's
  // rounding moves a point by less than 1e-15 (|lo| + |hi|) across an edge.
  const double margin = 1e-12 * (std::abs(lo) + std::abs(hi));
  const auto edge = [&](uint32_t r) {
    const double f = static_cast<double>(r << shift_) / 65536;
    return lo * (1 - f) + hi * f;
  };
  Interval span{row == 0 ? lo : edge(row) - margin,
                row + 1 == side_ ? hi : edge(row + 1) + margin};
  span.lo = std::max(span.lo, lo);
  span.hi = std::min(span.hi, hi);
  return span;
}

}  // namespace locator
