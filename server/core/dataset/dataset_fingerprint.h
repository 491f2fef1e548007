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

#include "locator/dataset.h"

namespace locator {

// Equal for datasets with equal contents (bit for bit); different, but for
// a 2^-64 chance, otherwise.
uint64_t DatasetFingerprint(const Dataset& dataset);

}  // namespace locator

#endif  // LOCATOR_CORE_DATASET_FINGERPRINT_H_
