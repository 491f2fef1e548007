// TriangulateGrid: a raster DEM (ElevationGrid) as a TIN within a stated
// vertical error, by greedy insertion (Garland and Heckbert, "Fast
// polygonal approximation of terrains and height fields", 1995).
//
// The domain. Cell (col, row) is the square between samples (col, row) and
// (col + 1, row + 1); it is valid when its four corners are valid (not
// NaN). The served domain is exactly the union of the valid cells: nodata
// samples are outside it and never interpolated across, a nodata region
// with valid cells around it is a hole, and the domain's boundary runs
// along cell edges. Every sample in the closed domain is valid; a valid
// sample that is the corner of no valid cell (a lone pixel, a one-pixel-
// wide line) is outside it (SimplificationStats::unserved_samples).
//
// The TIN. Its vertices are samples, their values the samples' own. Every
// corner of the domain's boundary is a vertex, and boundary edges are
// never crossed. Greedy insertion then adds the sample farthest from the
// TIN's surface, one at a time, keeping the triangulation constrained
// Delaunay, until every sample in the domain lies within max_error of the
// surface or max_points vertices are kept. With max_error == 0 and no
// binding max_points, every sample of the domain is a vertex and each
// valid cell is two triangles, split along its diagonal from (col, row) to
// (col + 1, row + 1): the grid's own structure, no Delaunay.
//
// Threads. With options.threads > 1 the grid is cut into tiles whose
// shared edges are simplified first, along the cut line alone, to
// max_error; each tile is then refined on its own with those vertices
// fixed, and the tiles are stitched along them (watertight by
// construction). When max_points binds, the build runs on one thread (the
// budget is global). The output is deterministic for a given input and
// options, thread count included.
//
// The certificate. stats->max_error is measured after the build over every
// sample of the domain, in dataset coordinates, with the engine's
// interpolation (Barycentric, EdgeBarycentric, a vertex's own value); any
// sample found beyond max_error (a rounding difference from the build's own
// arithmetic) is inserted too, so stats->max_error <= max_error unless
// max_points stopped the build.
//
// Output: `out` gets the vertices as points in row-major order of their
// samples, their values, the grid's crs and source, and the TIN as
// constraints.triangles (counter-clockwise in dataset coordinates): the
// served mesh is exactly these triangles, the surface the certificate
// measured.
//
// Thread-safety: a free function; concurrent calls share nothing.

#ifndef LOCATOR_CORE_TERRAIN_TRIANGULATE_GRID_H_
#define LOCATOR_CORE_TERRAIN_TRIANGULATE_GRID_H_

#include "common/elevation_grid.h"
#include "locator/dataset.h"
#include "locator/status.h"
#include "server/core/terrain/tin_options.h"

namespace locator {

// The TIN of `grid` within options.max_error (see above) into *out, its
// certificate into *stats. InvalidArgument naming what is wrong: a grid
// under 2 x 2 samples or over 2^24 on a side, values that do not match
// width * height, a non-finite or zero step or a non-finite origin, an
// infinite sample, no valid cell (all nodata), max_points below the
// vertices the domain's boundary needs, a TIN of more vertices than a
// serving mesh holds; or as CheckTinOptions.
Status TriangulateGrid(const ElevationGrid& grid, const TinOptions& options,
                       Dataset* out, SimplificationStats* stats);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_TRIANGULATE_GRID_H_
