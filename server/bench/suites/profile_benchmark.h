// The profile and interpolation benchmarks, on the synthetic terrain
// (surface_terrain.h), single-threaded:
//   profiles       breakpoints per second for polylines crossing about 10,
//                  100, ..., 10^5 triangle edges, each line traced whole by
//                  Engine::TraceProfile;
//   interpolation  ns per located point with linear, nearest and natural
//                  neighbour values, on the same queries in one run, and
//                  each one's cost relative to linear.
//
// Programs that print figures, never tests.

#ifndef LOCATOR_SERVER_BENCH_PROFILE_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_PROFILE_BENCHMARK_H_

#include <cstddef>
#include <ostream>

#include "locator/status.h"

namespace locator::bench {

struct SurfaceBenchOptions {
  size_t points = 1'000'000;
  // Interpolation: points located per method.
  size_t queries = 200'000;
};

Status RunProfileBenchmark(const SurfaceBenchOptions& options,
                           std::ostream& out);
Status RunInterpolationBenchmark(const SurfaceBenchOptions& options,
                                 std::ostream& out);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_PROFILE_BENCHMARK_H_
