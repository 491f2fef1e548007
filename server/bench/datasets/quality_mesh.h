// GenerateQualityMesh: the `mesh` kind of domain_datasets.h. CGAL's
// Delaunay_mesher_2 meshes NotchedSquare() minus RandomHoles() under a size
// field (the longest edge of a triangle with centroid p must not exceed
// s * (0.08 + min(1, |p - focus| / 0.35)), focus random per seed), with
// CGAL's default angle bound (about 20.6 degrees); s is calibrated so that
// the mesh has n points within 5%. The result is served as given: the mesh
// vertices and its in-domain triangles (counter-clockwise corner indices).
//
// The only CGAL code of the benchmark: it stays in quality_mesh.cc.
// Thread-safety: a free function over plain values.

#ifndef LOCATOR_SERVER_BENCH_QUALITY_MESH_H_
#define LOCATOR_SERVER_BENCH_QUALITY_MESH_H_

#include <cstddef>
#include <cstdint>

#include "server/bench/datasets/domain_datasets.h"

namespace locator::bench {

// A graded quality mesh with about n points (see above) for `seed`.
DomainDataset GenerateQualityMesh(size_t n, uint64_t seed);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_QUALITY_MESH_H_
