// StartTable: the self-tuning strategy's O(1) jump. An immutable two-level
// grid of walk starts: a coarse grid (the histogram's) whose cells are each
// refined into their own columns x rows sub-grid, chosen by the tuner from
// traffic, point density and the shape of the cell's triangles (a mesh
// stretched 50:1 gets sub-cells stretched alike). Every (sub-)cell stores the
// face containing its centre, so a query walks only from the centre of its
// own small cell. An unrefined cell finds its face on first use (a binary
// search along the mesh's curve, then a short walk): building a table reads
// only the refined cells' part of the mesh, so a mesh larger than RAM is
// not read whole by every re-tune, and a restart does not wait for it.
//
// A lookup costs one table read for an unrefined cell (1 x 1, the start is
// stored inline) and two for a refined one. A refined cell's starts live in
// their own immutable chunk, shared with the previous table when the cell's
// sub-grid did not change: a re-tune copies pointers, not starts.
//
// A table can also be built a bounded number of starts at a time
// (StartTable::Builder), so that a re-tune run inline in queries spreads its
// walks over many of them.
//
// Thread-safety: immutable after construction but for the unrefined cells'
// faces, each written once (atomically; every writer writes the same face)
// by the first Start() in it; Start() from any thread.
// A Builder is not thread-safe; its owner serialises calls.
// Invariant: every stored face is a face of the serving mesh it was built
// on, which must outlive the table, or kUnresolved in an unrefined cell.

#ifndef LOCATOR_CORE_START_TABLE_H_
#define LOCATOR_CORE_START_TABLE_H_

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "locator/geometry.h"
#include "server/core/mesh/scan_face.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tuning/query_histogram.h"

namespace locator {

// The sub-grid of one coarse cell: columns x rows sub-cells, each >= 1.
struct SubGrid {
  uint32_t columns = 1;
  uint32_t rows = 1;

  size_t cells() const { return size_t{columns} * rows; }
  bool operator==(const SubGrid&) const = default;
};

class StartTable {
 public:
  // A face of the serving mesh.
  using Face = uint32_t;
  // An unrefined cell's face before its first use.
  static constexpr Face kUnresolved = ServingMesh::kNoFace;

  // Bytes per stored start and per coarse cell (the cell, and the chunk's
  // control block and allocation header when refined), for budgeting.
  static constexpr size_t kBytesPerStart = sizeof(Face);
  static constexpr size_t kBytesPerCell = 64;

  class Builder;

  // sub_grids[c] is the sub-grid of coarse cell c. Cells whose sub-grid
  // equals that in `previous` (if given, same grid) copy its starts instead
  // of walking for them: a re-tune pays only for what moved.
  StartTable(const ServingMesh& mesh, const GridGeometry& grid,
             const std::vector<SubGrid>& sub_grids,
             const StartTable* previous = nullptr);

  // A table on `mesh` with the given sub-grids whose starts are `starts`,
  // cell by cell in row-major order, a refined cell's sub-cells row-major
  // (as Starts() lists them). Precondition: starts.size() is the sum of the
  // sub-grids' cells, and every face is a finite face of `mesh`, or
  // kUnresolved for an unrefined cell.
  StartTable(const ServingMesh& mesh, const GridGeometry& grid,
             const std::vector<SubGrid>& sub_grids,
             std::span<const Face> starts);

  const SubGrid& sub_grid(size_t cell) const { return cells_[cell].sub_grid; }
  // Every stored start, in the order the constructor above takes them
  // (kUnresolved for an unrefined cell not used yet).
  std::vector<Face> Starts() const;

  // The start face for q; adds the table reads made to *lookups.
  Face Start(const Point2& q, uint32_t* lookups) const {
    const Face face =
        std::atomic_ref<Face>(*const_cast<Face*>(Slot(q, lookups)))
            .load(std::memory_order_relaxed);
    return face != kUnresolved ? face : Resolve(q);
  }
  // Where Start() reads q's start, found with one read (of q's coarse
  // cell), so that a caller can prefetch it; adds the reads Start() makes
  // to *lookups.
  const Face* Slot(const Point2& q, uint32_t* lookups) const {
    const double gx = grid_.GridX(q.x);
    const double gy = grid_.GridY(q.y);
    const int cx = static_cast<int>(gx);
    const int cy = static_cast<int>(gy);
    const Cell& cell = cells_[static_cast<size_t>(cy) * grid_.size() + cx];
    if (!cell.leaves) {
      *lookups += 1;
      return &cell.face;
    }
    *lookups += 2;
    const uint32_t columns = cell.sub_grid.columns;
    const uint32_t rows = cell.sub_grid.rows;
    uint32_t sx = static_cast<uint32_t>((gx - cx) * columns);
    uint32_t sy = static_cast<uint32_t>((gy - cy) * rows);
    if (sx >= columns) sx = columns - 1;
    if (sy >= rows) sy = rows - 1;
    return &cell.leaves[size_t{sy} * columns + sx];
  }

  const GridGeometry& grid() const { return grid_; }
  // Number of stored starts.
  size_t start_count() const;
  size_t MemoryBytes() const;
  // Centres of about `max_points` stored starts, spread over the table.
  std::vector<Point2> SampleStartPoints(size_t max_points) const;

 private:
  struct Cell {
    // The start when the sub-grid is 1 x 1 (kUnresolved until first used).
    mutable Face face = kUnresolved;
    // columns x rows starts, row-major, when the sub-grid is larger.
    std::shared_ptr<const Face[]> leaves;
    SubGrid sub_grid;
  };

  // An empty table (every cell unresolved) on `mesh` for a Builder to fill.
  StartTable(const ServingMesh& mesh, const GridGeometry& grid)
      : mesh_(&mesh), grid_(grid), cells_(grid.cells()) {}

  // Finds, stores and returns the face of q's unrefined cell.
  Face Resolve(const Point2& q) const;

  const ServingMesh* mesh_;
  GridGeometry grid_;
  std::vector<Cell> cells_;
  size_t leaf_count_ = 0;
};

// Builds the table StartTable(mesh, grid, sub_grids, previous) would, in steps
// of a bounded number of work units: one unit per start located (by the
// filters along the scan of a cell's sub-cell centres, ScanFace, or a walk)
// and per cell copied from `previous`.
// Invariant: cells before the cursor (in serpentine order) are final.
class StartTable::Builder {
 public:
  // `mesh` and `previous` (if given) must outlive the builder.
  Builder(const ServingMesh& mesh, const GridGeometry& grid,
          std::vector<SubGrid> sub_grids, const StartTable* previous);

  // Does at most max_units (>= 1) units of work and adds their number to
  // *units; true once the table is complete.
  bool Step(size_t max_units, size_t* units);
  // The complete table. Precondition: Step() returned true.
  std::shared_ptr<const StartTable> Finish();

 private:
  friend class StartTable;

  const ServingMesh& mesh_;
  const std::vector<SubGrid> sub_grids_;
  const StartTable* previous_;
  StartTable table_;
  ScanFace scan_;  // along the sub-cell centres of the cell being filled
  Face hint_;
  size_t next_cell_ = 0;  // position in serpentine order
  size_t next_sub_ = 0;   // the same, within a refined cell being filled
  std::shared_ptr<Face[]> leaves_;  // that cell's starts, or null
  // The x of that cell's sub-cell centres by column, and their y by row.
  std::vector<double> column_x_;
  std::vector<double> row_y_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_START_TABLE_H_
