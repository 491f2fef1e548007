// The synthetic terrain the surface benchmarks run on: uniform points over
// a 10 km square with a smooth height field (a broad hill-and-valley wave
// on a gentle slope), so that profiles and rasters have non-trivial values
// and any two triangulations of the same points differ only by rounding.

#ifndef LOCATOR_SERVER_BENCH_SURFACE_TERRAIN_H_
#define LOCATOR_SERVER_BENCH_SURFACE_TERRAIN_H_

#include <cmath>
#include <cstdint>
#include <vector>

#include "locator/dataset.h"
#include "locator/dataset_sources.h"
#include "locator/geometry.h"

namespace locator::bench {

inline BoundingBox TerrainBox() { return BoundingBox{0, 0, 10000, 10000}; }

// The height at p, in metres.
inline double TerrainHeight(const Point2& p) {
  return 300 + 200 * std::sin(p.x / 1500) * std::cos(p.y / 1100) + 0.02 * p.x;
}

// `n` uniform points of TerrainBox().
inline std::vector<Point2> TerrainPoints(size_t n, uint64_t seed) {
  std::vector<Point2> points = GenerateUniform(n, seed).points;
  for (Point2& p : points) p = Point2{p.x * 10000, p.y * 10000};
  return points;
}

// The dataset of TerrainPoints() with their heights.
inline Dataset TerrainDataset(size_t n, uint64_t seed) {
  Dataset d;
  d.points = TerrainPoints(n, seed);
  for (const Point2& p : d.points) d.values.push_back(TerrainHeight(p));
  d.source = "terrain";
  return d;
}

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_SURFACE_TERRAIN_H_
