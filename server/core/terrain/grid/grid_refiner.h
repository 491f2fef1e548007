// GridRefiner: greedy insertion (Garland and Heckbert) on a TinMesh whose
// vertices are samples of an ElevationGrid, in grid coordinates. Each
// triangle scans the samples it covers (grid_raster.h) for the one farthest
// from its surface; a queue orders triangles by that error; the worst
// sample of the worst triangle is inserted, and the triangles the insertion
// rewrote are scanned again.
//
// Two measures of a triangle's error at a sample:
//   kPlane   the plane through its corners, in grid coordinates: what the
//            build refines with (a few operations per sample);
//   kServed  the engine's own interpolation in dataset coordinates
//            (Barycentric, EdgeBarycentric on an edge, a corner's own value)
//            with the corners in the order the output lists them: what the
//            certificate measures.
//
// A region may be a tile of the grid whose sides are cut lines shared with
// other tiles: the samples on a cut line's edges are fixed beforehand, so
// they are never scanned nor inserted, and the tiles stay watertight.
//
// Thread-safety: one GridRefiner per mesh; ScanAll() may use threads of its
// own, the rest runs on the caller's.

#ifndef LOCATOR_CORE_TERRAIN_GRID_REFINER_H_
#define LOCATOR_CORE_TERRAIN_GRID_REFINER_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/elevation_grid.h"
#include "locator/status.h"
#include "server/core/mesh/large_vector.h"
#include "server/core/terrain/grid/grid_domain.h"
#include "server/core/terrain/grid/grid_error.h"
#include "server/core/terrain/tin_mesh.h"
#include "server/core/terrain/tin_progress.h"
#include "server/core/terrain/triangle_queue.h"

namespace locator {

enum class GridMetric { kPlane, kServed };

// A region of the grid and which of its sides are cut lines.
struct GridRegion {
  GridRect rect;
  bool cut_left = false, cut_right = false;
  bool cut_top = false, cut_bottom = false;
};

class GridRefiner {
 public:
  // Refines `mesh` (which must outlive this) over `region` of `grid` until
  // every sample is within `target` of the surface.
  GridRefiner(const ElevationGrid& grid, TinMesh* mesh, GridMetric metric,
              const GridRegion& region, double target);

  // Measures every triangle, with up to `threads` threads; queues those
  // with a sample beyond the target.
  void ScanAll(unsigned threads);
  // Inserts the worst sample while one lies beyond the target and the mesh
  // has fewer than max_vertices vertices (0: no limit), reporting to
  // progress slot `slot` every few hundred insertions. Internal if an
  // insertion fails (the mesh is corrupt: a bug).
  Status Refine(uint64_t max_vertices, TinProgressReporter* progress,
                size_t slot);
  // The largest error of any triangle now; 0 if none has a sample left.
  // O(1) while a sample lies beyond the target, O(triangles) after.
  double MaxError() const;
  size_t MemoryBytes() const {
    return candidate_.capacity() * sizeof(uint64_t) +
           error_.capacity() * sizeof(double) + queue_.MemoryBytes();
  }

 private:
  std::array<GridPoint, 3> Corners(uint32_t t) const;
  // Whether edge i of t lies on a cut line (and is thus fixed).
  bool OnCut(uint32_t t, int i) const;
  WorstSample Measure(uint32_t t) const;
  // Hints that the grid rows a small triangle t covers are about to be
  // read.
  void PrefetchRows(uint32_t t) const;
  // Measures t, and queues it if its error exceeds the target (else keeps
  // it out of the queue).
  void Rescan(uint32_t t);

  const ElevationGrid& grid_;
  TinMesh* const mesh_;
  const GridMetric metric_;
  const GridRegion region_;
  const bool has_cuts_;
  const double target_;
  // The worst sample of each triangle (WorstSample::kNone if none) and its
  // error; only triangles whose error exceeds the target are queued.
  LargeVector<uint64_t> candidate_;
  LargeVector<double> error_;
  TriangleQueue queue_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_GRID_REFINER_H_
