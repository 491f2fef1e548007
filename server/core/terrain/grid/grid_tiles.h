// Greedy insertion on several threads: the grid is cut into tiles along
// full-length cut lines (columns and rows of samples). The samples of every
// cut line are simplified first, along the line alone, to max_error (a
// one-dimensional greedy insertion between the points where the domain's
// boundary meets or leaves the line, which are kept); each tile is then
// refined on its own, on any thread, with those points fixed on its
// border; and the tiles are stitched along them into one mesh, watertight
// by construction (both sides of a cut edge have the same vertices). The
// result depends on the plan, not on which thread built which tile.
//
// Thread-safety: free functions; BuildTiled runs `threads` threads.

#ifndef LOCATOR_CORE_TERRAIN_GRID_TILES_H_
#define LOCATOR_CORE_TERRAIN_GRID_TILES_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/elevation_grid.h"
#include "locator/status.h"
#include "server/core/terrain/grid/grid_domain.h"
#include "server/core/terrain/tin_mesh.h"
#include "server/core/terrain/tin_options.h"
#include "server/core/terrain/tin_progress.h"

namespace locator {

struct TilePlan {
  // Columns and rows of the cut lines, increasing, strictly inside the
  // grid; tile (i, j) spans cut_cols[i - 1]..cut_cols[i] (the grid's edges
  // at the ends) and likewise for rows.
  std::vector<int64_t> cut_cols;
  std::vector<int64_t> cut_rows;
  size_t tiles() const { return (cut_cols.size() + 1) * (cut_rows.size() + 1); }
};

// The tiles for `threads` threads on `grid`: a few per thread, so that
// threads that finish early take the tiles left.
TilePlan PlanTiles(const ElevationGrid& grid, unsigned threads);

// The samples each cut line keeps: the points where the boundary of the
// valid cells on either side meets or leaves it, where cut lines cross,
// and between those the samples a one-dimensional greedy insertion needs
// for every sample on the line to lie within max_error of the line's
// linear interpolation. Sorted by (row, col), no repeats.
std::vector<GridPoint> SimplifyCutLines(const ElevationGrid& grid,
                                        const CellMask& mask,
                                        const TilePlan& plan, double max_error);

// Refines every tile of `plan` within options.max_error on `threads`
// threads and stitches them into *mesh (empty on entry). Internal as
// GridRefiner::Refine.
Status BuildTiled(const ElevationGrid& grid, const CellMask& mask,
                  const TinOptions& options, const TilePlan& plan,
                  unsigned threads, TinProgressReporter* progress,
                  TinMesh* mesh);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_GRID_TILES_H_
