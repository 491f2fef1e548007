// RenderRows: fills rows of a raster (see raster.h) from the surface with
// scanline coherence: a cell clearly inside the previous cell's triangle
// is placed by three orientation filters on corners already loaded, and
// its value takes the cross products those filters computed (bit for bit
// a locate's value); any other cell's walk starts from the previous cell's
// triangle, and each row's first walk from the previous row's first
// triangle, so a cell costs about one orientation test per triangle edge
// the scan crosses. Exact like every walk: CGAL's orientation_2 decides the
// triangle, also for centres on edges and vertices.
//
// Thread-safety: a pure function over an immutable ServingMesh; threads
// render disjoint rows at once.

#ifndef LOCATOR_CORE_RASTER_RENDER_H_
#define LOCATOR_CORE_RASTER_RENDER_H_

#include <cstdint>
#include <span>

#include "locator/raster.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

// Renders rows [first_row, first_row + rows) of `spec` into `out` (rows x
// spec.width values, row by row, west to east), starting the first walk at
// face `hint`. Preconditions: CheckRasterSpec(spec).ok(), the rows lie
// within spec.height, and CheckInterpolation(spec.interpolation) is OK for
// the mesh's dataset.
void RenderRows(const ServingMesh& mesh, uint32_t hint, const RasterSpec& spec,
                uint32_t first_row, uint32_t rows, double* out);

// Renders the value at each of `points` into `out` (points.size() values)
// as RenderRows renders cells: the points come in rows of `row_length`
// (the last may be shorter), each walk starts from the previous point's
// triangle and each row's first from the previous row's first triangle, so
// points in scan order (a raster's cell centres mapped to another CRS) cost
// about what the cells of a raster do. A non-finite point gets `nodata`.
// Preconditions: CheckInterpolation(how) is OK for the mesh's dataset;
// row_length >= 1.
void RenderPoints(const ServingMesh& mesh, uint32_t hint,
                  std::span<const Point2> points, size_t row_length,
                  Interpolation how, double nodata, double* out);

// Renders the gradient of the facet at each of `points` into `out`
// (points.size() gradients), walking as RenderPoints does. A point on an
// edge or a vertex takes the in-domain face the walk found there; a point
// with no facet gets NaN. Precondition: row_length >= 1.
void RenderGradients(const ServingMesh& mesh, uint32_t hint,
                     std::span<const Point2> points, size_t row_length,
                     FacetGradient* out);

}  // namespace locator

#endif  // LOCATOR_CORE_RASTER_RENDER_H_
