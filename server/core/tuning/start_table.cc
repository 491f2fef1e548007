#include "server/core/tuning/start_table.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "server/core/geometry/wide_math.h"
#include "server/core/mesh/mesh_walk.h"

namespace locator {

namespace {

// Finite for any cell of any grid (GridLine), so every walk has a finite
// target.
Point2 SubCellCentre(const BoundingBox& cell, const SubGrid& sub_grid,
                     uint32_t sx, uint32_t sy) {
  return Point2{GridLine(cell.min_x, cell.max_x, sx + 0.5, sub_grid.columns),
                GridLine(cell.min_y, cell.max_y, sy + 0.5, sub_grid.rows)};
}

}  // namespace

StartTable::StartTable(const ServingMesh& mesh, const GridGeometry& grid,
                       const std::vector<SubGrid>& sub_grids,
                       const StartTable* previous)
    : mesh_(&mesh), grid_(grid) {
  Builder builder(mesh, grid, sub_grids, previous);
  size_t units = 0;
  builder.Step(SIZE_MAX, &units);
  *this = std::move(builder.table_);
}

StartTable::Builder::Builder(const ServingMesh& mesh, const GridGeometry& grid,
                             std::vector<SubGrid> sub_grids,
                             const StartTable* previous)
    : mesh_(mesh),
      sub_grids_(std::move(sub_grids)),
      previous_(previous),
      table_(mesh, grid),
      scan_(mesh),
      hint_(mesh.DefaultStart()) {}

bool StartTable::Builder::Step(size_t max_units, size_t* units) {
  // Visit cells and sub-cells in serpentine order so that each centre is
  // located by a short walk from the previous one.
  const int g = table_.grid_.size();
  const size_t end = table_.cells_.size();
  size_t done = 0;
  while (next_cell_ < end && done < max_units) {
    const int row = static_cast<int>(next_cell_ / g);
    const int k = static_cast<int>(next_cell_ % g);
    const int col = (row % 2 == 0) ? k : g - 1 - k;
    const size_t index = static_cast<size_t>(row) * g + col;
    Cell& cell = table_.cells_[index];
    const BoundingBox box = table_.grid_.CellBox(col, row);
    const SubGrid sub = sub_grids_[index];
    if (!leaves_) {
      if (sub.cells() > 1) table_.leaf_count_ += sub.cells();
      if (previous_ && previous_->cells_[index].sub_grid == sub) {
        ++done;
        const Cell& kept = previous_->cells_[index];
        cell.sub_grid = kept.sub_grid;
        cell.leaves = kept.leaves;
        // Queries on the previous table may be resolving it right now.
        cell.face =
            std::atomic_ref<Face>(kept.face).load(std::memory_order_relaxed);
        if (cell.leaves) hint_ = cell.leaves[0];
        ++next_cell_;
        continue;
      }
      cell.sub_grid = sub;
      if (sub.cells() == 1) {
        ++done;
        cell.face = kUnresolved;  // found on first use (Resolve)
        ++next_cell_;
        continue;
      }
      leaves_ = std::make_shared_for_overwrite<Face[]>(sub.cells());
      // From a triangle near the first sub-cell along the curve (a binary
      // search), not from the last refined cell's: a walk across the cells
      // between reads a page per triangle, all of a mesh larger than RAM.
      const Point2 first = SubCellCentre(box, sub, 0, 0);
      hint_ = FaceNear(mesh_, mesh_.TriangleNear(first), first);
      scan_.Forget();
      // A centre's x depends on its column alone and its y on its row alone.
      column_x_.resize(sub.columns);
      for (uint32_t sx = 0; sx < sub.columns; ++sx) {
        column_x_[sx] = SubCellCentre(box, sub, sx, 0).x;
      }
      row_y_.resize(sub.rows);
      for (uint32_t sy = 0; sy < sub.rows; ++sy) {
        row_y_[sy] = SubCellCentre(box, sub, 0, sy).y;
      }
    }
    uint32_t sy = static_cast<uint32_t>(next_sub_ / sub.columns);
    uint32_t j = static_cast<uint32_t>(next_sub_ % sub.columns);
    for (; next_sub_ < sub.cells() && done < max_units; ++next_sub_, ++done) {
      const uint32_t sx = (sy % 2 == 0) ? j : sub.columns - 1 - j;
      const Point2 centre{column_x_[sx], row_y_[sy]};
      hint_ =
          scan_.Holds(centre) ? scan_.face() : scan_.WalkTo(centre, hint_).face;
      leaves_[size_t{sy} * sub.columns + sx] = hint_;
      if (++j == sub.columns) {
        j = 0;
        ++sy;
      }
    }
    if (next_sub_ < sub.cells()) break;
    cell.leaves = std::move(leaves_);  // leaves_ is null again
    next_sub_ = 0;
    ++next_cell_;
  }
  *units += done;
  return next_cell_ == end;
}

std::shared_ptr<const StartTable> StartTable::Builder::Finish() {
  return std::make_shared<const StartTable>(std::move(table_));
}

StartTable::StartTable(const ServingMesh& mesh, const GridGeometry& grid,
                       const std::vector<SubGrid>& sub_grids,
                       std::span<const Face> starts)
    : mesh_(&mesh), grid_(grid), cells_(grid.cells()) {
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

StartTable::Face StartTable::Resolve(const Point2& q) const {
  const int cx = static_cast<int>(grid_.GridX(q.x));
  const int cy = static_cast<int>(grid_.GridY(q.y));
  const Cell& cell = cells_[static_cast<size_t>(cy) * grid_.size() + cx];
  const BoundingBox box = grid_.CellBox(cx, cy);
  const Point2 centre = SubCellCentre(box, cell.sub_grid, 0, 0);
  const Face face = FaceNear(*mesh_, mesh_->TriangleNear(centre), centre);
  std::atomic_ref<Face>(cell.face).store(face, std::memory_order_relaxed);
  return face;
}

std::vector<StartTable::Face> StartTable::Starts() const {
  std::vector<Face> starts;
  starts.reserve(start_count());
  for (const Cell& cell : cells_) {
    if (cell.leaves) {
      starts.insert(starts.end(), cell.leaves.get(),
                    cell.leaves.get() + cell.sub_grid.cells());
    } else {
      starts.push_back(
          std::atomic_ref<Face>(cell.face).load(std::memory_order_relaxed));
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
