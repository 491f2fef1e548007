// MeshVectors: the arrays of a serving mesh built in memory, owned by the
// mesh as its storage (serving_mesh.h). Both builders fill one: the CGAL
// one (triangulation_serving.cc) and the tiled one (mesh_assembly.h).
//
// Thread-safety: a plain value until the mesh owns it; immutable after.

#ifndef LOCATOR_CORE_TILING_MESH_VECTORS_H_
#define LOCATOR_CORE_TILING_MESH_VECTORS_H_

#include <cstdint>

#include "locator/geometry.h"
#include "server/core/mesh/large_vector.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

class MeshVectors : public ServingMesh::Storage {
 public:
  LargeVector<MeshTriangle> triangles;
  LargeVector<Point2> points;
  LargeVector<double> values;
  LargeVector<uint32_t> ids;
  LargeVector<uint32_t> hull;

  // Arrays viewing these vectors, the other fields left to the caller.
  ServingMesh::Arrays Views() const {
    ServingMesh::Arrays arrays;
    arrays.triangles = triangles;
    arrays.points = points;
    arrays.values = values;
    arrays.ids = ids;
    arrays.hull = hull;
    return arrays;
  }
};

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_MESH_VECTORS_H_
