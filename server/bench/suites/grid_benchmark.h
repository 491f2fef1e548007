// The grid benchmark: locator against gdal_grid -a linear (Debian's
// gdal-bin) on the same points and the same raster, in one run.
//
// It writes N uniform points of a smooth terrain as CSV (and the OGR VRT
// gdal_grid reads them through), then times, each --repeats times,
// alternating:
//   locator   end to end in this process: parse the CSV, triangulate (the
//             jump-and-walk strategy: a one-shot job learns nothing), render
//             every cell (rows split over the threads), write a tiled
//             GeoTIFF with RasterWriter;
//   gdal_grid the whole gdal_grid process run on the VRT, writing its
//             GeoTIFF;
// and locator's render alone on the already built engine. Then it compares
// the two rasters where both have a value: the maximum absolute difference,
// also relative to the z range, and the cells where only one has a value.
//
// A program that prints figures, never a test.

#ifndef LOCATOR_SERVER_BENCH_GRID_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_GRID_BENCHMARK_H_

#include <cstdint>
#include <ostream>
#include <string>

#include "locator/status.h"

namespace locator::bench {

struct GridBenchOptions {
  size_t points = 1'000'000;
  uint32_t size = 2048;  // width = height
  int repeats = 1;
  unsigned threads = 2;
  // Where the CSV, the VRT and both GeoTIFFs go (created if missing).
  std::string work_dir = "/tmp/locator-grid-bench";
};

// Runs the benchmark and prints its report to `out`.
Status RunGridBenchmark(const GridBenchOptions& options, std::ostream& out);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_GRID_BENCHMARK_H_
