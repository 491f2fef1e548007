// CellGrid: a 2^level x 2^level grid of cells over the points' bounding
// box, the unit in which the tiled build sorts points, cuts tiles and grows
// halos.
//
// A cell is a block of 2^(16 - level) x 2^(16 - level) cells of HilbertKey's
// 2^16 x 2^16 grid (hilbert.h), and cells are numbered along the Hilbert
// curve of their own level. So sorting points by their HilbertKey (the
// serving mesh's vertex order) also sorts them by cell, and a range of cell
// numbers is a compact region.
//
// Column() and Row() are monotone (HilbertCell): every point whose x lies in
// [x0, x1] has a column between Column(x0) and Column(x1). The certification of
// a tile's triangles (halo_cells.h) relies on this, with RowSpan(), to know
// every cell a region meets without rounding a point into the wrong cell.
//
// Thread-safety: immutable; every method may be called from any thread.

#ifndef LOCATOR_CORE_TILING_CELL_GRID_H_
#define LOCATOR_CORE_TILING_CELL_GRID_H_

#include <cstddef>
#include <cstdint>

#include "common/hilbert.h"
#include "locator/geometry.h"

namespace locator {

class CellGrid {
 public:
  // The finest level: 4^12 cells, so that a tile's per-cell state stays
  // small; larger inputs get fuller cells.
  static constexpr int kMaxLevel = 12;

  struct Interval {
    double lo;
    double hi;
  };

  // The grid of 2^level x 2^level cells over `box` (not empty).
  // Precondition: 0 <= level <= kMaxLevel.
  CellGrid(const BoundingBox& box, int level);

  // The level at which `points` points average about `per_cell` per cell.
  static int LevelFor(size_t points, size_t per_cell);

  const BoundingBox& box() const { return box_; }
  int level() const { return level_; }
  // Cells per row and per column.
  uint32_t side() const { return side_; }
  size_t num_cells() const { return size_t{side_} * side_; }

  // p's position along the Hilbert curve of the 2^16 grid over box():
  // HilbertKey(p, box()).
  uint32_t FineKey(const Point2& p) const { return HilbertKey(p, box_); }
  // The cell whose fine keys include `fine_key`.
  uint32_t CellOfKey(uint32_t fine_key) const {
    return static_cast<uint32_t>(uint64_t{fine_key} >> (2 * shift_));
  }
  uint32_t Column(double x) const {
    return HilbertCell(x, box_.min_x, box_.max_x) >> shift_;
  }
  uint32_t Row(double y) const {
    return HilbertCell(y, box_.min_y, box_.max_y) >> shift_;
  }
  // The number of cell (column, row) along this level's Hilbert curve.
  uint32_t Cell(uint32_t column, uint32_t row) const;
  // The column and row of cell number `cell`: the inverse of Cell().
  void CellPosition(uint32_t cell, uint32_t* column, uint32_t* row) const;
  // A y interval, within the box, holding every y of the box whose Row()
  // is `row`: exact band edges widened by far more than their rounding.
  Interval RowSpan(uint32_t row) const;

 private:
  BoundingBox box_;
  int level_;
  int shift_;  // 16 - level
  uint32_t side_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_CELL_GRID_H_
