// ReferenceGreedyGrid: straightforward greedy insertion (Garland and
// Heckbert) on one thread, with CGAL's constrained Delaunay triangulation
// and a priority queue whose stale entries are skipped when popped. It is
// the yardstick TriangulateGrid is compared with: the vertices the same
// error needs (tests, locator-surface-bench's comparison column). It
// refines the same domain with the same measure (WorstPlaneSample), but
// shares none of TriangulateGrid's mesh, queue or tiles.
//
// Thread-safety: a free function.

#ifndef LOCATOR_CORE_TERRAIN_REFERENCE_GREEDY_H_
#define LOCATOR_CORE_TERRAIN_REFERENCE_GREEDY_H_

#include <array>
#include <cstdint>
#include <vector>

#include "common/elevation_grid.h"
#include "locator/status.h"

namespace locator {

struct ReferenceTin {
  uint64_t vertices = 0;
  // In-domain triangles, counter-clockwise in grid coordinates, as sample
  // indices (row * width + col).
  std::vector<std::array<uint64_t, 3>> triangles;
  // The largest error left by the plane measure.
  double max_error = 0;
};

// Greedy insertion on `grid` until every sample of its domain lies within
// max_error of the plane of its triangle, or max_points vertices (0: no
// limit). InvalidArgument if the grid has no valid cell.
Status ReferenceGreedyGrid(const ElevationGrid& grid, double max_error,
                           uint64_t max_points, ReferenceTin* out);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_REFERENCE_GREEDY_H_
