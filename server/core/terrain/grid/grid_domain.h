// The domain of an ElevationGrid (see triangulate_grid.h): which cells are
// valid (CellMask), and the first mesh of a rectangle of the grid, whose
// triangles cover exactly the valid cells inside it and whose vertices are
// the corners of their boundary (BuildRegionMesh).
//
// Coordinates are grid coordinates: x = col, y = row (integers, so every
// predicate on them is exact).
//
// Thread-safety: a CellMask is immutable after construction; the functions
// are free functions.

#ifndef LOCATOR_CORE_TERRAIN_GRID_DOMAIN_H_
#define LOCATOR_CORE_TERRAIN_GRID_DOMAIN_H_

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "common/elevation_grid.h"
#include "locator/status.h"
#include "server/core/terrain/tin_mesh.h"

namespace locator {

// A grid point, in grid coordinates.
struct GridPoint {
  int64_t x = 0;  // column
  int64_t y = 0;  // row
  bool operator==(const GridPoint& o) const { return x == o.x && y == o.y; }
};

// The samples [col0, col1] x [row0, row1] and the cells between them: the
// whole grid, or a tile of it.
struct GridRect {
  int64_t col0 = 0, row0 = 0, col1 = 0, row1 = 0;
  bool Contains(const GridPoint& p) const {
    return p.x >= col0 && p.x <= col1 && p.y >= row0 && p.y <= row1;
  }
  // Whether p lies on the rectangle's border.
  bool OnBorder(const GridPoint& p) const {
    return Contains(p) &&
           (p.x == col0 || p.x == col1 || p.y == row0 || p.y == row1);
  }
};

// Which cells of a grid have four valid corners: one bit per cell.
class CellMask {
 public:
  explicit CellMask(const ElevationGrid& grid);

  // Cell (col, row), between samples (col, row) and (col + 1, row + 1);
  // false outside the grid.
  bool Valid(int64_t col, int64_t row) const {
    if (col < 0 || row < 0 || col >= cols_ || row >= rows_) return false;
    return (bits_[row * words_per_row_ + col / 64] >> (col % 64)) & 1;
  }
  // Sets bit i of *words (resized to hold `count` bits) to Valid(col0 + i,
  // row), for 0 <= i < count.
  void RowBits(int64_t row, int64_t col0, int64_t count,
               std::vector<uint64_t>* words) const;
  // Whether every cell of `rect` is valid.
  bool AllValid(const GridRect& rect) const;
  uint64_t valid_cells() const { return valid_cells_; }
  // Valid samples that are the corner of no valid cell.
  uint64_t unserved_samples() const { return unserved_samples_; }
  size_t MemoryBytes() const { return bits_.capacity() * 8; }

 private:
  int64_t cols_ = 0;  // cells per row: width - 1
  int64_t rows_ = 0;  // rows of cells: height - 1
  int64_t words_per_row_ = 0;
  std::vector<uint64_t> bits_;
  uint64_t valid_cells_ = 0;
  uint64_t unserved_samples_ = 0;
};

// The boundary of the valid cells inside `rect`: maximal straight runs of
// cell edges between break vertices (the boundary's corners, and the
// points of `fixed` on it), as pairs of indices into *points.
void TraceBoundary(const CellMask& mask, const GridRect& rect,
                   std::span<const GridPoint> fixed,
                   std::vector<GridPoint>* points,
                   std::vector<std::pair<size_t, size_t>>* runs);

// The first mesh of the valid cells inside `rect` into *mesh (which must be
// empty): the constrained Delaunay triangulation of their boundary, whose
// vertices are the boundary's corners and the points of `fixed` that lie on
// it (points on the rectangle's border, which an adjacent tile shares), and
// whose boundary edges run between consecutive ones; only the triangles
// inside the domain are kept (none if no cell of `rect` is valid). Mesh
// vertices are grid points; the boundary edges have no twin.
void BuildRegionMesh(const CellMask& mask, const GridRect& rect,
                     std::span<const GridPoint> fixed, TinMesh* mesh);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_GRID_DOMAIN_H_
