// CellSource: where a tile's triangulation reads its points, cell by cell.
// In memory that is SortedPoints; an out-of-core build reads cells from its
// binned files, so a tile holds only its own points and its halo.
//
// Vertex indices are global: the position of the vertex in the order of
// SortedPoints (by cell along the curve, then fine key, then id), so that
// the vertices of a range of cells are a range of indices.
//
// Thread-safety: implementations must allow concurrent const calls (one
// tile per thread reads at once).

#ifndef LOCATOR_CORE_TILING_CELL_SOURCE_H_
#define LOCATOR_CORE_TILING_CELL_SOURCE_H_

#include <cstdint>
#include <vector>

#include "locator/geometry.h"

namespace locator {

struct TileVertex {
  Point2 point;
  uint32_t index = 0;  // global vertex index
};

class CellSource {
 public:
  virtual ~CellSource() = default;
  // The number of vertices in cell number `cell` of the grid.
  virtual uint32_t CellSize(uint32_t cell) const = 0;
  // The index of the first vertex of cell `cell`; the others follow.
  virtual uint32_t CellStart(uint32_t cell) const = 0;
  // Appends the vertices of cell `cell` to *out, in index order.
  virtual void ReadCell(uint32_t cell, std::vector<TileVertex>* out) const = 0;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_CELL_SOURCE_H_
