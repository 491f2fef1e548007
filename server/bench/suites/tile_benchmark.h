// The terrain tile benchmark: milliseconds per 256x256 terrain tile
// (RenderTerrainTile: PROJ from EPSG:3857, the scan-coherent walk, the
// encoding and libpng), single-threaded, on the synthetic terrain
// (surface_terrain.h) placed in UTM zone 33N, for zooms from the one whose
// single tile holds the terrain to the one whose pixels are about the
// points' spacing; each zoom's row also splits the time into its parts,
// and gives the milliseconds per hillshade tile (RenderHillshadeTile, the
// default light) of the same tiles.
//
// A program that prints figures, never a test.

#ifndef LOCATOR_SERVER_BENCH_TILE_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_TILE_BENCHMARK_H_

#include <cstddef>
#include <ostream>

#include "locator/status.h"

namespace locator::bench {

struct TileBenchOptions {
  size_t points = 1'000'000;
  // Tiles rendered per zoom (those nearest the terrain's centre).
  int tiles = 16;
};

// Runs the benchmark and prints its report to `out`.
Status RunTileBenchmark(const TileBenchOptions& options, std::ostream& out);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_TILE_BENCHMARK_H_
