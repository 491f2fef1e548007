// The synthetic dataset generators of dataset.h: deterministic for a seed
// on every platform (their own uniform mapping, see random.h).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "common/random.h"
#include "locator/dataset_sources.h"

namespace locator {

Dataset GenerateUniform(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Dataset ds;
  ds.points.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    // x is drawn before y: the order is part of the dataset's definition.
    const double x = UnitDouble(rng);
    const double y = UnitDouble(rng);
    ds.points.push_back({x, y});
  }
  ds.source = "uniform:" + std::to_string(n) + ":" + std::to_string(seed);
  return ds;
}

Dataset GenerateClusters(size_t n, size_t k, uint64_t seed) {
  struct Blob {
    Point2 center;
    double sigma;
  };
  // k == 0 has no meaning; one blob beats dividing by zero.
  k = std::max<size_t>(k, 1);
  std::mt19937_64 rng(seed);
  std::vector<Blob> blobs(k);
  for (Blob& b : blobs) {
    b.center.x = UniformDouble(rng, 0.1, 0.9);
    b.center.y = UniformDouble(rng, 0.1, 0.9);
    b.sigma = UniformDouble(rng, 0.01, 0.06);
  }
  Dataset ds;
  ds.points.reserve(n);
  while (ds.points.size() < n) {
    const Blob& b = blobs[UniformIndex(rng, k)];
    // Box-Muller; 1 - u is in (0, 1], so the log is finite.
    const double radius = std::sqrt(-2.0 * std::log(1.0 - UnitDouble(rng)));
    const double angle = 2.0 * std::numbers::pi * UnitDouble(rng);
    const Point2 p{b.center.x + b.sigma * radius * std::cos(angle),
                   b.center.y + b.sigma * radius * std::sin(angle)};
    // Rejection rather than clamping: clamping would pile points up on the
    // border (and create duplicates there).
    if (p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0) {
      ds.points.push_back(p);
    }
  }
  ds.source = "clusters:" + std::to_string(n) + ":" + std::to_string(k) + ":" +
              std::to_string(seed);
  return ds;
}

}  // namespace locator
