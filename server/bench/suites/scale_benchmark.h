// RunScale: wall-clock ns per locate at large n, for every workload and
// strategy and for CGAL's own methods (no hint, last answer as hint,
// Triangulation_hierarchy_2), checking every answer against CGAL; plus build
// times and bytes of each structure. Workloads: common/workload.h's and a
// row-order raster on uniform points; queries near the points and a raster
// on a clustered dataset; uniform queries and a raster on the TIN of a
// fractal DEM with n vertices (TriangulateGrid with max_points n), served
// as a mesh given as triangles (its build row: given-mesh-dem). Strategy rows
// also report re-tunes, the tuner's time share, sampled latency and batch
// (LocateMany) ns per point.

#ifndef LOCATOR_SERVER_BENCH_SCALE_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_SCALE_BENCHMARK_H_

#include <cstddef>
#include <string>
#include <vector>

#include "locator/status.h"
#include "locator/tuning_options.h"
#include "server/bench/bench_report.h"

namespace locator::bench {

struct ScaleOptions {
  std::vector<size_t> sizes = {100000, 1000000};
  size_t warmup = 5000;
  size_t queries = 100000;
  // walk and CGAL without a hint are O(sqrt n) per query: fewer queries.
  size_t slow_queries = 2000;
  int repeats = 5;
  // Only these workloads / strategies (names as in the report); empty: all.
  std::vector<std::string> workloads;
  std::vector<std::string> strategies;
  TuningOptions tuning;
};

// Fails with Internal if any answer disagrees with CGAL, InvalidArgument on
// an unknown workload or strategy name.
Status RunScale(const ScaleOptions& options, BenchReport* report);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_SCALE_BENCHMARK_H_
