#include "server/core/start_table.h"

#include <algorithm>

#include "server/core/mesh_walk.h"

namespace locator {

namespace {

Point2 SubCellCentre(const BoundingBox& cell, const SubGrid& sub_grid,
                     uint32_t sx, uint32_t sy) {
  return Point2{cell.min_x + (sx + 0.5) * cell.width() / sub_grid.columns,
                cell.min_y + (sy + 0.5) * cell.height() / sub_grid.rows};
}

}  // namespace

StartTable::StartTable(const ServingMesh& mesh, const GridGeometry& grid,
                       const std::vector<SubGrid>& sub_grids,
                       const StartTable* previous)
    : grid_(grid), cells_(grid.cells()) {
  // Visit cells and sub-cells in serpentine order so that each centre is
  // located by a short walk from the previous one.
  Face hint = mesh.DefaultStart();
  const int g = grid_.size();
  for (int row = 0; row < g; ++row) {
    for (int k = 0; k < g; ++k) {
      const int col = (row % 2 == 0) ? k : g - 1 - k;
      const size_t index = static_cast<size_t>(row) * g + col;
      Cell& cell = cells_[index];
      const BoundingBox box = grid_.CellBox(col, row);
      const SubGrid sub = sub_grids[index];
      if (sub.cells() > 1) leaf_count_ += sub.cells();
      if (previous && previous->cells_[index].sub_grid == sub) {
        cell = previous->cells_[index];
        hint = cell.leaves ? cell.leaves[0] : cell.face;
        continue;
      }
      cell.sub_grid = sub;
      if (sub.cells() == 1) {
        hint = cell.face = FaceNear(mesh, hint, SubCellCentre(box, sub, 0, 0));
        continue;
      }
      auto leaves = std::make_shared_for_overwrite<Face[]>(sub.cells());
      for (uint32_t sy = 0; sy < sub.rows; ++sy) {
        for (uint32_t j = 0; j < sub.columns; ++j) {
          const uint32_t sx = (sy % 2 == 0) ? j : sub.columns - 1 - j;
          hint = FaceNear(mesh, hint, SubCellCentre(box, sub, sx, sy));
          leaves[size_t{sy} * sub.columns + sx] = hint;
        }
      }
      cell.leaves = std::move(leaves);
    }
  }
}

StartTable::StartTable(const GridGeometry& grid,
                       const std::vector<SubGrid>& sub_grids,
                       std::span<const Face> starts)
    : grid_(grid), cells_(grid.cells()) {
  size_t next = 0;
  for (size_t index = 0; index < cells_.size(); ++index) {
    Cell& cell = cells_[index];
    cell.sub_grid = sub_grids[index];
    const size_t n = cell.sub_grid.cells();
    if (n == 1) {
      cell.face = starts[next++];
      continue;
    }
    auto leaves = std::make_shared_for_overwrite<Face[]>(n);
    std::copy_n(starts.begin() + next, n, leaves.get());
    next += n;
    leaf_count_ += n;
    cell.leaves = std::move(leaves);
  }
}

std::vector<StartTable::Face> StartTable::Starts() const {
  std::vector<Face> starts;
  starts.reserve(start_count());
  for (const Cell& cell : cells_) {
    if (cell.leaves) {
      starts.insert(starts.end(), cell.leaves.get(),
                    cell.leaves.get() + cell.sub_grid.cells());
    } else {
      starts.push_back(cell.face);
    }
  }
  return starts;
}

size_t StartTable::start_count() const {
  size_t direct = 0;
  for (const Cell& c : cells_) direct += !c.leaves;
  return direct + leaf_count_;
}

size_t StartTable::MemoryBytes() const {
  return cells_.size() * kBytesPerCell + leaf_count_ * kBytesPerStart;
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
      const SubGrid& sub = cells_[static_cast<size_t>(row) * g + col].sub_grid;
      const BoundingBox box = grid_.CellBox(col, row);
      for (uint32_t sy = 0; sy < sub.rows; ++sy) {
        for (uint32_t sx = 0; sx < sub.columns; ++sx, ++index) {
          if (index % step == 0) {
            out.push_back(SubCellCentre(box, sub, sx, sy));
          }
        }
      }
    }
  }
  return out;
}

}  // namespace locator
