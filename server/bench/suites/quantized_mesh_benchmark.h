// The quantized-mesh benchmark: milliseconds per Cesium terrain tile
// (RenderQuantizedMesh: the TIN cut out, mapped to lon/lat by PROJ,
// clipped, simplified within the level's geometric error and encoded),
// single-threaded, on the synthetic terrain (surface_terrain.h) placed in
// UTM zone 33N, for every level from 0 (one tile holds all the points) to
// the one whose tiles hold a few dozen: the tiles round the terrain's
// centre, with their sizes.
//
// A program that prints figures, never a test.

#ifndef LOCATOR_SERVER_BENCH_QUANTIZED_MESH_BENCHMARK_H_
#define LOCATOR_SERVER_BENCH_QUANTIZED_MESH_BENCHMARK_H_

#include <cstddef>
#include <ostream>

#include "locator/status.h"

namespace locator::bench {

struct QuantizedMeshBenchOptions {
  size_t points = 1'000'000;
};

// Runs the benchmark and prints its report to `out`.
Status RunQuantizedMeshBenchmark(const QuantizedMeshBenchOptions& options,
                                 std::ostream& out);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_QUANTIZED_MESH_BENCHMARK_H_
