// BuildTiledMesh: the serving mesh of the canonical Delaunay triangulation
// of a plain point set (no constraints), built from tiles with certified
// halos on several threads, without one global CGAL triangulation.
//
// Steps (each in its own file):
//   1. SortPoints: the distinct points in the mesh's vertex order, grouped
//      by the cells of a grid (sorted_points.h), and the hull of all of
//      them (hull_edges.h);
//   2. CutTiles: ranges of cells along the Hilbert curve, about
//      tile_vertices vertices each; TriangulateTile on `threads` threads:
//      each tile's own points and a halo, certified (tile_triangulation.h);
//   3. AssembleServingMesh: the owned triangles in the mesh's order, their
//      neighbours and the hull (mesh_assembly.h).
// The mesh depends on the points only: not on the tiles, the threads or
// the order of the input (but for ids, which are input indices). Its
// triangles are exactly Triangulation::Build's for the same points, both
// being the canonical Delaunay triangulation (canonical_delaunay.h).
//
// A tile only reads cells through a CellSource, so an out-of-core build can
// triangulate tiles whose points it reads from disk (cell_source.h).
//
// Thread-safety: a pure function; it starts and joins its own threads.

#ifndef LOCATOR_CORE_TILING_TILED_BUILD_H_
#define LOCATOR_CORE_TILING_TILED_BUILD_H_

#include <cstddef>
#include <span>

#include "locator/geometry.h"
#include "locator/status.h"
#include "server/core/mesh/mesh_file.h"

namespace locator {

struct TiledBuildOptions {
  // Threads that sort, triangulate tiles and assemble (at least 1).
  unsigned threads = 1;
  // Vertices per tile; 0 picks TileVerticesFor(vertices, threads).
  size_t tile_vertices = 0;
  // Points per grid cell, on average: the grain of halos.
  size_t cell_points = 4;
};

// Seconds per step and what the tiles did, for benchmarks.
struct TiledBuildStats {
  double sort_seconds = 0;  // checks, sort, duplicates, hull
  double tiles_seconds = 0;
  double assembly_seconds = 0;  // the serving mesh and its facts
  size_t tiles = 0;
  int grid_level = 0;
  // Points tiles inserted from other tiles' cells, summed.
  size_t halo_points = 0;
  // The most certification rounds a tile took.
  int max_rounds = 0;
};

// The default tile size: about four tiles per thread (so that threads
// finish together), at least 32768 vertices.
size_t TileVerticesFor(size_t vertices, unsigned threads);

// Builds the serving mesh and facts of `points` (with `values`: empty or
// one per point) into *out, as described above. Vertex ids are input
// indices, repeats merged into the first, as Triangulation::Build.
// InvalidArgument as Triangulation::Build for bad points (non-finite,
// fewer than 3 distinct, all collinear, values of another count) or too
// many of them; ResourceExhausted if memory runs out; Internal if the
// tiles do not fit together (a bug, never a wrong mesh).
Status BuildTiledMesh(std::span<const Point2> points,
                      std::span<const double> values,
                      const TiledBuildOptions& options, BuiltMesh* out,
                      TiledBuildStats* stats = nullptr);

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_TILED_BUILD_H_
