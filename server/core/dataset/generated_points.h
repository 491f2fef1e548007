// GeneratedPoints: the points of a generator spec (uniform:, clusters:),
// drawn one at a time, so that a build can stream a generated dataset of
// any size instead of holding it (GenerateUniform and GenerateClusters
// collect the same draws).
//
// Deterministic: the same spec gives the same points in the same order on
// every platform (kGeneratorVersion changes when it would not).
//
// Thread-safety: one object per thread.

#ifndef LOCATOR_CORE_DATASET_GENERATED_POINTS_H_
#define LOCATOR_CORE_DATASET_GENERATED_POINTS_H_

#include <cstddef>
#include <random>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/geometry.h"

namespace locator {

class GeneratedPoints {
 public:
  explicit GeneratedPoints(const GeneratorSpec& spec);

  // The next point. Precondition: fewer than spec.n points drawn so far
  // (more are well defined, but not part of the dataset).
  Point2 Next();

 private:
  struct Blob {
    Point2 center;
    double sigma;
  };
  Point2 NextInBlob();

  std::mt19937_64 rng_;
  bool clusters_;
  std::vector<Blob> blobs_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_DATASET_GENERATED_POINTS_H_
