// RunTileSet: serving a tile set (locator-build's out-of-core build, its
// mesh file mapped as locatord maps it) against a dataset served in RAM:
// seconds from a cold page cache to an engine ready to serve; ns per
// locate on a hot region (the 1-cluster workload, after as many untimed
// queries for the tuner to learn it), on the tile set and on the in-RAM
// dataset; uniform random locates over the tile set, the first pass (pages
// read as the walks need them) and the second (warm); the resident memory
// after each step, anonymous and file-backed apart.
//
// A program that prints figures, never a test: the machine is shared and
// noisy, so compare within one run, by the ratios.

#ifndef LOCATOR_SERVER_BENCH_TILESET_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_TILESET_BENCHMARK_H_

#include <cstddef>
#include <ostream>
#include <string>

#include "locator/status.h"

namespace locator::bench {

struct TileSetBenchOptions {
  std::string manifest;  // DIR/manifest.json
  // The dataset served in RAM for the hot-region comparison.
  std::string ram_dataset = "uniform:10000000";
  size_t queries = 100000;
};

// Prints one line per figure (markdown table). NotFound or InvalidArgument
// for a manifest or mesh file that cannot be served.
Status RunTileSet(const TileSetBenchOptions& options, std::ostream& out);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_TILESET_BENCHMARK_H_
