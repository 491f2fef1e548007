#include "server/core/start_table.h"

#include <algorithm>

#include "server/core/walk.h"

namespace locator {

namespace {

Point2 SubCellCentre(const BoundingBox& cell, uint32_t r, uint32_t sx,
                     uint32_t sy) {
  return Point2{cell.min_x + (sx + 0.5) * cell.width() / r,
                cell.min_y + (sy + 0.5) * cell.height() / r};
}

}  // namespace

StartTable::StartTable(const Triangulation& t, const GridGeometry& grid,
                       const std::vector<uint32_t>& resolution,
                       const StartTable* previous)
    : grid_(grid), cells_(grid.cells()) {
  size_t leaves = 0;
  for (uint32_t r : resolution) leaves += r > 1 ? size_t{r} * r : 0;
  leaves_.resize(leaves);

  // Visit cells and sub-cells in serpentine order so that each centre is
  // located by a short walk from the previous one.
  Face_handle hint = t.DefaultStart();
  const int g = grid_.size();
  uint32_t offset = 0;
  for (int row = 0; row < g; ++row) {
    for (int k = 0; k < g; ++k) {
      const int col = (row % 2 == 0) ? k : g - 1 - k;
      const size_t index = static_cast<size_t>(row) * g + col;
      Cell& cell = cells_[index];
      const BoundingBox box = grid_.CellBox(col, row);
      const uint32_t r = std::max<uint32_t>(1, resolution[index]);
      cell.resolution = r;
      if (previous && previous->cells_[index].resolution == r) {
        const Cell& old = previous->cells_[index];
        cell.face = old.face;
        if (r > 1) {
          cell.offset = offset;
          std::copy_n(previous->leaves_.begin() + old.offset, r * r,
                      leaves_.begin() + offset);
          offset += r * r;
        }
        continue;
      }
      if (r == 1) {
        hint = cell.face = FaceNear(t, hint, SubCellCentre(box, 1, 0, 0));
        continue;
      }
      cell.offset = offset;
      for (uint32_t sy = 0; sy < r; ++sy) {
        for (uint32_t j = 0; j < r; ++j) {
          const uint32_t sx = (sy % 2 == 0) ? j : r - 1 - j;
          hint = FaceNear(t, hint, SubCellCentre(box, r, sx, sy));
          leaves_[offset + sy * r + sx] = hint;
        }
      }
      offset += r * r;
    }
  }
}

size_t StartTable::start_count() const {
  size_t direct = 0;
  for (const Cell& c : cells_) direct += c.resolution == 1;
  return direct + leaves_.size();
}

size_t StartTable::MemoryBytes() const {
  return cells_.capacity() * sizeof(Cell) +
         leaves_.capacity() * sizeof(Face_handle);
}

std::vector<Point2> StartTable::SampleStartPoints(size_t max_points) const {
  const size_t total = start_count();
  const size_t step =
      std::max<size_t>(1, (total + max_points - 1) / max_points);
  std::vector<Point2> out;
  size_t index = 0;
  const int g = grid_.size();
  for (int row = 0; row < g; ++row) {
    for (int col = 0; col < g; ++col) {
      const uint32_t r = cells_[static_cast<size_t>(row) * g + col].resolution;
      const BoundingBox box = grid_.CellBox(col, row);
      for (uint32_t sy = 0; sy < r; ++sy) {
        for (uint32_t sx = 0; sx < r; ++sx, ++index) {
          if (index % step == 0) out.push_back(SubCellCentre(box, r, sx, sy));
        }
      }
    }
  }
  return out;
}

}  // namespace locator
