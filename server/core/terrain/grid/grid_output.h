// The Dataset a grid TIN is served as (see triangulate_grid.h): its
// vertices as points in row-major order of their samples, with their
// samples' values, and its triangles as constraints.triangles,
// counter-clockwise in dataset coordinates.
//
// Thread-safety: free functions.

#ifndef LOCATOR_CORE_TERRAIN_GRID_OUTPUT_H_
#define LOCATOR_CORE_TERRAIN_GRID_OUTPUT_H_

#include "common/elevation_grid.h"
#include "locator/dataset.h"
#include "locator/status.h"
#include "server/core/terrain/grid/grid_domain.h"
#include "server/core/terrain/tin_mesh.h"

namespace locator {

// Renumbers `mesh`, whose vertices are grid samples in grid
// coordinates, in row-major order of its vertices, and its triangles by
// their first corner in that order: a scan of the triangles then reads the
// grid nearly in order.
void SortRowMajor(TinMesh* mesh);

// Writes `mesh`, whose vertices are samples of `grid` in grid coordinates
// in row-major order (SortRowMajor), into *out (crs and source from the
// grid). InvalidArgument if it has more
// vertices or triangles than a serving mesh holds, or if placing the
// samples in dataset coordinates rounds a triangle flat (a step too small
// for the origin's magnitude).
Status WriteGridTin(const ElevationGrid& grid, const TinMesh& mesh,
                    Dataset* out);

// Writes the grid's own TIN into *out: every sample of the domain is a
// vertex and each valid cell two triangles, split along the diagonal from
// (col, row) to (col + 1, row + 1). Errors as WriteGridTin.
Status WriteGridCells(const ElevationGrid& grid, const CellMask& mask,
                      Dataset* out);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_GRID_OUTPUT_H_
