#include "server/core/terrain/grid/grid_certificate.h"

#include "common/status_macros.h"
#include "server/core/terrain/grid/grid_refiner.h"

namespace locator {

Status CertifyGridTin(const ElevationGrid& grid, const TinOptions& options,
                      unsigned threads, TinProgressReporter* progress,
                      TinMesh* mesh, double* certified) {
  const GridRegion whole{
      GridRect{0, 0, grid.width - int64_t{1}, grid.height - int64_t{1}}};
  GridRefiner refiner(grid, mesh, GridMetric::kServed, whole,
                      options.max_error);
  refiner.ScanAll(threads);
  // The samples left beyond the target differ from the build's measure by
  // rounding only: usually none, a few at most.
  RETURN_IF_ERROR(refiner.Refine(options.max_points, progress, 0));
  *certified = refiner.MaxError();
  return Status::OK();
}

}  // namespace locator
