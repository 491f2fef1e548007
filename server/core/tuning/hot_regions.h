// FindHotRegions: turns a query histogram into a few rectangles where the
// queries concentrate (the paper's Section IV approximation of the C_i).
//
// A cell is hot when its count is at least `density_factor` times the mean
// count per cell (and at least `min_count`), so uniform traffic yields no
// regions. Hot cells are covered greedily by maximal rectangles, and the pair
// of rectangles whose union wastes the least area is merged until at most
// `max_regions` remain.

#ifndef LOCATOR_CORE_HOT_REGIONS_H_
#define LOCATOR_CORE_HOT_REGIONS_H_

#include <cstddef>
#include <vector>

#include "locator/geometry.h"
#include "server/core/tuning/query_histogram.h"

namespace locator {

struct HotRegionOptions {
  double density_factor = 4.0;
  double min_count = 3.0;
  size_t max_regions = 8;
};

std::vector<BoundingBox> FindHotRegions(
    const GridGeometry& grid, const std::vector<double>& counts,
    const HotRegionOptions& options = HotRegionOptions());

}  // namespace locator

#endif  // LOCATOR_CORE_HOT_REGIONS_H_
