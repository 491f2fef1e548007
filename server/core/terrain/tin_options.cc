#include "server/core/terrain/tin_options.h"

#include <cmath>
#include <string>

namespace locator {

Status CheckTinOptions(const TinOptions& options) {
  if (!std::isfinite(options.max_error) || options.max_error < 0) {
    return Status::InvalidArgument(
        "max_error is " + std::to_string(options.max_error) +
        "; it must be a finite number >= 0 (0 keeps every sample)");
  }
  if (!(options.progress_interval_s > 0) ||
      !std::isfinite(options.progress_interval_s)) {
    return Status::InvalidArgument(
        "progress_interval_s is " +
        std::to_string(options.progress_interval_s) +
        "; it must be a finite number of seconds > 0");
  }
  return Status::OK();
}

void RecordTinMade(const Dataset& tin,
                   std::chrono::steady_clock::time_point start,
                   SimplificationStats* stats) {
  stats->vertices = tin.points.size();
  stats->triangles = tin.constraints.triangles.size();
  stats->build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
}

}  // namespace locator
