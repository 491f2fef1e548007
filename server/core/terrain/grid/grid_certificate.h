// The certificate of a grid TIN: every sample of the domain measured on the
// TIN as the engine will serve it (GridMetric::kServed), and any sample
// found beyond the target inserted, so that the error reported is the one
// served and within the target unless max_points stopped the build.
//
// Thread-safety: a free function; it may use `threads` threads of its own.

#ifndef LOCATOR_CORE_TERRAIN_GRID_CERTIFICATE_H_
#define LOCATOR_CORE_TERRAIN_GRID_CERTIFICATE_H_

#include "common/elevation_grid.h"
#include "locator/status.h"
#include "server/core/terrain/tin_mesh.h"
#include "server/core/terrain/tin_options.h"
#include "server/core/terrain/tin_progress.h"

namespace locator {

// Measures every sample of the domain on `mesh` (vertices: samples of
// `grid` in grid coordinates) with the served interpolation, inserts the
// worst sample while one exceeds options.max_error and max_points allows,
// and sets *certified to the largest error left. Internal as
// GridRefiner::Refine.
Status CertifyGridTin(const ElevationGrid& grid, const TinOptions& options,
                      unsigned threads, TinProgressReporter* progress,
                      TinMesh* mesh, double* certified);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_GRID_CERTIFICATE_H_
