// SortedPoints: the distinct points of a dataset in the serving mesh's
// vertex order, grouped by the cells of a CellGrid: what the tiled build
// triangulates and the mesh's vertex arrays.
//
// Order: by FineKey (the Hilbert key over the box of all input points),
// ties by id, exactly as ServingMesh orders vertices; so a cell's vertices
// are consecutive and vertex indices of a range of cells are a range.
// Repeated points are merged into their first occurrence, whose input
// index is the vertex's public id (as Triangulation::Build does).
//
// Thread-safety: a plain value.

#ifndef LOCATOR_CORE_TILING_SORTED_POINTS_H_
#define LOCATOR_CORE_TILING_SORTED_POINTS_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "locator/geometry.h"
#include "server/core/mesh/large_vector.h"
#include "server/core/tiling/cells/cell_grid.h"
#include "server/core/tiling/cells/cell_source.h"

namespace locator {

struct SortedPoints {
  // The grid over the box of the input points.
  CellGrid grid{BoundingBox{0, 0, 1, 1}, 0};
  // Distinct points in vertex order, and each one's public id.
  LargeVector<Point2> points;
  LargeVector<uint32_t> ids;
  // cell_start[c] .. cell_start[c + 1] are the vertices of cell c
  // (grid.num_cells() + 1 entries).
  std::vector<uint32_t> cell_start;
  size_t input_points = 0;

  size_t size() const { return points.size(); }
  size_t duplicates() const { return input_points - points.size(); }
  uint32_t CellSize(uint32_t cell) const {
    return cell_start[cell + 1] - cell_start[cell];
  }
};

// The cells of SortedPoints, for the tiles' triangulations.
class SortedPointsSource : public CellSource {
 public:
  explicit SortedPointsSource(const SortedPoints& sorted) : s_(sorted) {}
  uint32_t CellSize(uint32_t cell) const override { return s_.CellSize(cell); }
  uint32_t CellStart(uint32_t cell) const override {
    return s_.cell_start[cell];
  }
  void ReadCell(uint32_t cell, std::vector<TileVertex>* out) const override {
    for (uint32_t v = s_.cell_start[cell]; v < s_.cell_start[cell + 1]; ++v) {
      out->push_back(TileVertex{s_.points[v], v});
    }
  }

 private:
  const SortedPoints& s_;
};

// Appends the distinct points of `input` to *points, and their indices in
// `input` to *indices, in the order of `items` (FineKey << 32 | index into
// `input`, sorted), a repeat merged into the first of its key group, and
// counts each in cell_sizes[its cell] (grid.num_cells() entries): the
// grouping step of SortPoints, which the out-of-core build runs per bin.
void AppendDistinct(std::span<const uint64_t> items,
                    std::span<const Point2> input, const CellGrid& grid,
                    LargeVector<Point2>* points, LargeVector<uint32_t>* indices,
                    std::span<uint32_t> cell_sizes);

// Sorts `input` (finite points, at most ServingMesh::kMaxElements of them,
// not empty) on `threads` threads into *out, with cells holding about
// `per_cell` points on average.
void SortPoints(std::span<const Point2> input, size_t per_cell,
                unsigned threads, SortedPoints* out);

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_SORTED_POINTS_H_
