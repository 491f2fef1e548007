// The synthetic dataset generators of dataset.h: deterministic for a seed
// on every platform (their own uniform mapping, see random.h).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/random.h"
#include "locator/dataset_sources.h"
#include "server/core/dataset/generated_points.h"

namespace locator {

GeneratedPoints::GeneratedPoints(const GeneratorSpec& spec)
    : rng_(spec.seed), clusters_(spec.clusters) {
  if (!clusters_) return;
  // k == 0 has no meaning; one blob beats dividing by zero.
  blobs_.resize(std::max<size_t>(spec.k, 1));
  for (Blob& b : blobs_) {
    b.center.x = UniformDouble(rng_, 0.1, 0.9);
    b.center.y = UniformDouble(rng_, 0.1, 0.9);
    b.sigma = UniformDouble(rng_, 0.01, 0.06);
  }
}

Point2 GeneratedPoints::Next() {
  if (clusters_) return NextInBlob();
  // x is drawn before y: the order is part of the dataset's definition.
  const double x = UnitDouble(rng_);
  const double y = UnitDouble(rng_);
  return {x, y};
}

Point2 GeneratedPoints::NextInBlob() {
  for (;;) {
    const Blob& b = blobs_[UniformIndex(rng_, blobs_.size())];
    // Box-Muller; 1 - u is in (0, 1], so the log is finite.
    const double radius = std::sqrt(-2.0 * std::log(1.0 - UnitDouble(rng_)));
    const double angle = 2.0 * std::numbers::pi * UnitDouble(rng_);
    const Point2 p{b.center.x + b.sigma * radius * std::cos(angle),
                   b.center.y + b.sigma * radius * std::sin(angle)};
    // Rejection rather than clamping: clamping would pile points up on the
    // border (and create duplicates there).
    if (p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0) return p;
  }
}

namespace {

Dataset Generate(const GeneratorSpec& spec) {
  GeneratedPoints source(spec);
  Dataset ds;
  ds.points.reserve(spec.n);
  for (size_t i = 0; i < spec.n; ++i) ds.points.push_back(source.Next());
  ds.source = spec.clusters
                  ? "clusters:" + std::to_string(spec.n) + ":" +
                        std::to_string(spec.k) + ":" + std::to_string(spec.seed)
                  : "uniform:" + std::to_string(spec.n) + ":" +
                        std::to_string(spec.seed);
  return ds;
}

}  // namespace

Dataset GenerateUniform(size_t n, uint64_t seed) {
  return Generate(
      GeneratorSpec{.clusters = false, .n = n, .k = 1, .seed = seed});
}

Dataset GenerateClusters(size_t n, size_t k, uint64_t seed) {
  return Generate(
      GeneratorSpec{.clusters = true, .n = n, .k = k, .seed = seed});
}

}  // namespace locator
