// RunTileSet: serving a tile set (locator-build's out-of-core build, its
// mesh file mapped as locatord maps it) against a dataset served in RAM:
// seconds from a cold page cache to an engine ready to serve (the first
// start reads and checks the whole mesh file, a restart maps it checked,
// see MapMeshFile); uniform random locates over the tile set, the first
// pass (pages read as the walks need them) and the second (warm); ns per
// locate on a hot region (the 1-cluster workload, after as many untimed
// queries for the tuner to learn it) on the tile set and on the same
// region in RAM (the generator's points around it, built in memory; tile
// sets of generators only); the resident memory after each step,
// anonymous and file-backed apart.
//
// A program that prints figures, never a test: the machine is shared and
// noisy, so compare within one run, by the ratios.

#ifndef LOCATOR_SERVER_BENCH_TILESET_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_TILESET_BENCHMARK_H_

#include <cstddef>
#include <ostream>
#include <string>

#include "locator/status.h"
#include "locator/tuning_options.h"

namespace locator::bench {

struct TileSetBenchOptions {
  std::string manifest;  // DIR/manifest.json
  size_t queries = 100000;
  // Both engines' tuning (locator-bench --budget).
  TuningOptions tuning;
  // Also build the source (a generator) in memory: the same mesh arrays,
  // the same answers to verify_queries uniform queries (Internal if not).
  bool verify = false;
  size_t verify_queries = 1000000;
};

// Prints one line per figure (markdown table). NotFound or InvalidArgument
// for a manifest or mesh file that cannot be served.
Status RunTileSet(const TileSetBenchOptions& options, std::ostream& out);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_TILESET_BENCHMARK_H_
