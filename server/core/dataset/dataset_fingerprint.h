// DatasetFingerprint: a 64-bit XXH3 digest of everything a triangulation is
// built from (points, values, breaklines, rings, .poly segments and hole
// seeds, mesh triangles), computed before triangulating: the key of the
// dataset's mesh file (mesh_cache.h). Not of the source name, the CRS or
// regional attributes, which do not change the mesh. Reads every byte once.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_DATASET_FINGERPRINT_H_
#define LOCATOR_CORE_DATASET_FINGERPRINT_H_

#include <cstdint>
#include <span>

#include "locator/dataset.h"
#include "server/core/geometry/xxh3_digest.h"

namespace locator {

// Equal for datasets with equal contents (bit for bit); different, but for
// a 2^-64 chance, otherwise.
uint64_t DatasetFingerprint(const Dataset& dataset);

// DatasetFingerprint of a plain point set (no constraints) fed in pieces,
// for a build that streams its points: Begin the points with their count,
// add them in order, Begin the values (0 without values), add them, Finish.
class PointSetFingerprint {
 public:
  void Begin(uint64_t count) { digest_.Add(&count, sizeof(count)); }
  void AddPoints(std::span<const Point2> points) {
    digest_.Add(points.data(), points.size_bytes());
  }
  void AddValues(std::span<const double> values) {
    digest_.Add(values.data(), values.size_bytes());
  }
  // The fingerprint; call once, after the values.
  uint64_t Finish();

 private:
  Xxh3Digest digest_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_DATASET_FINGERPRINT_H_
