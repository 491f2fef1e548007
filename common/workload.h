// Workload: synthetic query streams from the paper's Section III (and a few
// beyond it), defined on the unit square and mapped into a target box.
//
// Names (lower case):
//   uniform     uniform over the box.
//   1-cluster   the square (0.48,0.48)-(0.52,0.52).
//   3-cluster   the squares (0.47,0.17)-(0.53,0.23), (0.77,0.77)-(0.83,0.83),
//               (0.17,0.77)-(0.23,0.83), one chosen uniformly per query.
//   d-cluster   within +-0.02 (vertically) of the diagonal y = x.
//   x-cluster   within +-0.02 of either diagonal, each chosen with p = 1/2.
//   mixed       half 3-cluster, half uniform.
//   drift       a 1-cluster-sized square (0.04 wide) that jumps to a new
//               random place every `drift_period` queries.
//
// Thread-safety: a Workload is not thread-safe; give each thread its own
// (different seeds give independent streams).

#ifndef LOCATOR_COMMON_WORKLOAD_H_
#define LOCATOR_COMMON_WORKLOAD_H_

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"

namespace locator {

enum class WorkloadKind {
  kUniform,
  kOneCluster,
  kThreeCluster,
  kDCluster,
  kXCluster,
  kMixed,
  kDrift,
};

// All kinds, in the order above, and their names.
const std::vector<WorkloadKind>& AllWorkloadKinds();
std::string_view WorkloadName(WorkloadKind kind);
// Parses a name above; InvalidArgument listing the valid names otherwise.
Status ParseWorkloadKind(std::string_view name, WorkloadKind* kind);

class Workload {
 public:
  static constexpr uint64_t kDefaultDriftPeriod = 5000;

  // Queries of `kind` mapped from the unit square into `box`.
  Workload(WorkloadKind kind, const BoundingBox& box, uint64_t seed,
           uint64_t drift_period = kDefaultDriftPeriod);

  WorkloadKind kind() const { return kind_; }
  // The next query point. Always finite and inside the box.
  Point2 Next();
  // Number of queries generated so far.
  uint64_t count() const { return count_; }

 private:
  Point2 NextUnit();  // in the unit square
  Point2 InSquare(double x0, double y0, double side);
  Point2 NearDiagonal(bool anti);

  WorkloadKind kind_;
  BoundingBox box_;
  std::mt19937_64 rng_;
  uint64_t drift_period_;
  uint64_t count_ = 0;
  Point2 drift_corner_{0.48, 0.48};
};

// The first `count` queries of a Workload(kind, box, seed).
std::vector<Point2> WorkloadQueries(WorkloadKind kind, const BoundingBox& box,
                                    size_t count, uint64_t seed);

// A raster scan: the centres of a columns x rows grid over `box`, row by row
// from (min_x, min_y), x increasing within a row; columns =
// ceil(sqrt(count)), and the last row may be partial.
std::vector<Point2> RasterQueries(const BoundingBox& box, size_t count);

}  // namespace locator

#endif  // LOCATOR_COMMON_WORKLOAD_H_
