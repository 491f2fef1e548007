// RunBuild: seconds from points in memory to a mesh ready to serve, for
// today's CGAL build (Triangulation::Build: one constrained Delaunay
// triangulation, then the serving mesh) against the tiled build
// (server/core/tiling/tiled_build.h) on each thread count, alternating the
// builders within each repeat so that they see the same noise. Per build:
// wall and CPU seconds, the tiled build's phases (sort with the hull, tiles,
// assembly), the strategy's set-up ("ready" adds it), and the peak of the
// resident set above what it was before, per input point.
//
// A program that prints figures, never a test: the machine is shared and
// noisy, so compare within one run, by the per-repeat ratios.

#ifndef LOCATOR_SERVER_BENCH_BUILD_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_BUILD_BENCHMARK_H_

#include <cstddef>
#include <ostream>
#include <vector>

#include "locator/status.h"

namespace locator::bench {

struct BuildOptions {
  std::vector<size_t> sizes = {1000000};
  std::vector<unsigned> threads = {1, 2};
  int repeats = 3;
  // Also check that the tiled mesh is the CGAL build's, array for array,
  // and canonical (timing that check).
  bool verify = false;
  bool csv = false;
};

// Prints one row per build, then a summary per builder and the ratios.
// Internal if a verified tiled mesh differs from the CGAL build's.
Status RunBuild(const BuildOptions& options, std::ostream& out);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_BUILD_BENCHMARK_H_
