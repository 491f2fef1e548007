// CheckMeshArrays: whether arrays are safe to serve from: every index a
// query can follow stays inside the arrays, whatever bytes they came from.
// CompareMeshArrays: whether two builds made the same mesh, byte for byte.
// A mesh file's contents pass it before they are served (after its
// checksum and fingerprint, which vouch that the mesh is the triangulation
// a build of the dataset wrote).
//
// It checks bounds and each triangle's own orientation, not how triangles
// fit together: a file forged with a recomputed checksum can still hold a
// mesh whose triangles overlap or whose neighbours disagree, which would
// give wrong answers or make walks wander, but never read outside the
// arrays or divide by a zero area. The mesh cache directory is trusted as
// the binary is. Linear scans only.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_MESH_CHECK_H_
#define LOCATOR_CORE_MESH_CHECK_H_

#include "locator/status.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

// OK if: at least 3 vertices, 1 in-domain face and 3 hull edges, and
// in_domain at most the faces; ids and values one per vertex; every
// coordinate and the box finite; every id below input_points + V
// (constraint points follow the input points); every corner a vertex and
// every triangle strictly counter-clockwise (CGAL's exact orientation);
// every neighbour a face or a position in the hull; every hull entry an
// edge of a face whose neighbour field names that entry back, each edge
// ending where the one before it starts (a closed ring). Otherwise
// InvalidArgument naming the first violation.
Status CheckMeshArrays(const ServingMesh::Arrays& a);

// OK if `got` and `want` hold the same bytes in every array and the same
// domain count, box, input count and digest; otherwise Internal naming the
// first that differs.
Status CompareMeshArrays(const ServingMesh::Arrays& got,
                         const ServingMesh::Arrays& want);

}  // namespace locator

#endif  // LOCATOR_CORE_MESH_CHECK_H_
