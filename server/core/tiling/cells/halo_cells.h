// HaloCells: which cells of the grid one tile has seen, i.e. inserted every
// point of, and which unseen cells a region meets. A tile's triangle is
// final (certified) when its closed circumdisk meets only seen cells: then
// every point on or inside its circle is in the tile's triangulation, so
// the triangle is in the global one too (canonical_delaunay.h explains why
// ties on the circle need nothing more).
//
// Regions are tested row by row of cells: the rows the region spans, and in
// each row the columns its chord spans, both through CellGrid's monotone
// Column()/Row() and widened by far more than the rounding of the chord, so
// that no cell a region meets is missed. Cells without points count as seen.
//
// The tile grows its halo inside a window of cells (its own cells' box
// grown by a reach it doubles when needed), so that a region reaching far,
// like a hull edge's outer half-plane, pulls in the nearest cells first.
//
// Thread-safety: one HaloCells per thread; the source may be shared.

#ifndef LOCATOR_CORE_TILING_HALO_CELLS_H_
#define LOCATOR_CORE_TILING_HALO_CELLS_H_

#include <cstdint>
#include <vector>

#include "locator/geometry.h"
#include "server/core/tiling/cells/cell_grid.h"
#include "server/core/tiling/cells/cell_source.h"
#include "server/core/tiling/cells/circumdisk.h"

namespace locator {

class HaloCells {
 public:
  // What a region test found.
  struct Cover {
    // Every cell the region meets has been seen.
    bool covered = true;
    // The region meets cells outside the window.
    bool beyond = false;
  };
  struct Window {
    uint32_t min_column, min_row, max_column, max_row;
  };

  HaloCells(const CellGrid& grid, const CellSource& source);

  // Forgets every cell and sets an empty wanted list (cost: the cells
  // touched since the last Clear()).
  void Clear();
  void SetWindow(const Window& window) { window_ = window; }
  const Window& window() const { return window_; }
  // Whether the window spans the whole grid.
  bool WindowIsGrid() const;

  // Records that every point of cell (column, row) has been inserted.
  void MarkSeen(uint32_t column, uint32_t row);
  bool Seen(uint32_t column, uint32_t row) const {
    return state_[Index(column, row)] == kSeen;
  }

  // Tests a region against the seen cells; every unseen cell with points
  // that it meets inside the window is added to wanted() (once).
  Cover CoverDisk(const Disk& disk);
  // The closed half-plane right of the directed line p -> q.
  Cover CoverRightOf(const Point2& p, const Point2& q);
  // The cells [min_column, max_column] x [min_row, max_row] of the window
  // (beyond if the box leaves it).
  Cover CoverBox(const Window& box);
  // The whole window (for a tile whose points are still all collinear, or
  // a triangle whose circumdisk has no finite bound): beyond unless the
  // window is the grid.
  Cover CoverWindow();

  // The cells (numbers along the curve) wanted since the last TakeWanted(),
  // which marks them seen: the caller inserts their points now.
  std::vector<uint32_t> TakeWanted();

 private:
  enum State : uint8_t { kUnknown = 0, kWanted = 1, kSeen = 2 };

  size_t Index(uint32_t column, uint32_t row) const {
    return size_t{row} * grid_.side() + column;
  }
  // Whether `box` is small and all its cells have been seen (cells outside
  // the window never are).
  bool AllSeen(const Window& box) const;
  // Visits the cells of row `row` whose columns are in [c0, c1], updating
  // `cover`: cells outside the window make it beyond.
  void CoverCells(uint32_t row, uint32_t c0, uint32_t c1, Cover* cover);
  // CoverCells for the columns of the x interval [x0, x1], widened by slack.
  void CoverSpan(uint32_t row, double x0, double x1, Cover* cover);
  void SetState(size_t index, State state);

  const CellGrid& grid_;
  const CellSource& source_;
  // Coordinates are at most this far from what exact arithmetic would give
  // anywhere in a region test (a relative 1e-12 of the magnitudes).
  double slack_;
  Window window_{0, 0, 0, 0};
  std::vector<uint8_t> state_;
  std::vector<size_t> touched_;
  // Wanted cells: their numbers along the curve and their state indices.
  std::vector<uint32_t> wanted_;
  std::vector<size_t> wanted_index_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_HALO_CELLS_H_
