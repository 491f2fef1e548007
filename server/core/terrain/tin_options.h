// What the terrain simplifier is asked (TinOptions) and what it certifies
// (SimplificationStats): shared by TriangulateGrid (triangulate_grid.h) and
// SimplifyPoints (simplify_points.h).
//
// Thread-safety: plain values. The progress callback is called from the
// building threads, one call at a time.

#ifndef LOCATOR_CORE_TERRAIN_TIN_OPTIONS_H_
#define LOCATOR_CORE_TERRAIN_TIN_OPTIONS_H_

#include <chrono>
#include <cstdint>
#include <functional>

#include "locator/dataset.h"
#include "locator/engine_info.h"
#include "locator/status.h"

namespace locator {

// A snapshot of a build in progress.
struct TinProgress {
  uint64_t vertices = 0;  // kept so far
  double max_error = 0;   // the largest error still to be removed
  double seconds = 0;     // since the build began
};

struct TinOptions {
  // E, in the values' units: the TIN is refined until every source sample
  // lies within E of its linear surface. 0 keeps every sample.
  double max_error = 0;
  // At most this many vertices (0: no limit); whichever of max_error and
  // max_points is reached first ends the build.
  uint64_t max_points = 0;
  // How many threads build (0 counts as 1).
  unsigned threads = 1;
  // Called at least every progress_interval_s seconds while building, from
  // the building thread(s), never two calls at once.
  std::function<void(const TinProgress&)> progress;
  double progress_interval_s = 5;
};

// OK if `options` can be honoured; InvalidArgument naming the field and its
// range otherwise (max_error NaN, negative or infinite; a progress interval
// that is not positive).
Status CheckTinOptions(const TinOptions& options);

// Fills the counts of `tin`, the TIN just made, into *stats, and the
// seconds since `start` as its build time.
void RecordTinMade(const Dataset& tin,
                   std::chrono::steady_clock::time_point start,
                   SimplificationStats* stats);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_TIN_OPTIONS_H_
