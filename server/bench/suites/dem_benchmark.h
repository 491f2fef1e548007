// The DEM benchmark, in the shape of hmm's README table: fractal DEMs of
// 1187^2, 2373^2, 4745^2 and 9490^2 pixels (the same terrain sampled at
// each size, FractalTerrain), triangulated by TriangulateGrid within
// e = 0.01, 0.001, 0.0005 and 0.0001 of the height range.
//
// Each build runs in a child process of its own (fork after the DEM is
// made), so that its peak memory is its own: the child's VmHWM, which
// counts the DEM it reads (shared with the parent) and everything the
// build allocates. Per row it prints the seconds on 1 and on 2 threads
// (the best of --dem-repeats runs each, alternating), their ratio, the
// triangles and vertices (2 threads), the vertices of the straightforward
// single-threaded greedy insertion (ReferenceGreedyGrid) and how far the
// 2-thread build is from it, the peak memory, and the certified max error
// over the target.
//
// A program that prints figures, never a test.

#ifndef LOCATOR_SERVER_BENCH_DEM_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_DEM_BENCHMARK_H_

#include <cstdint>
#include <ostream>
#include <vector>

#include "locator/status.h"

namespace locator::bench {

struct DemBenchOptions {
  std::vector<uint32_t> sizes = {1187, 2373, 4745, 9490};
  std::vector<double> errors = {0.01, 0.001, 0.0005, 0.0001};
  int repeats = 1;
  // Run ReferenceGreedyGrid for the comparison column.
  bool reference = true;
  uint64_t seed = 1;
};

// Runs the benchmark and prints its table to `out`.
Status RunDemBenchmark(const DemBenchOptions& options, std::ostream& out);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_DEM_BENCHMARK_H_
