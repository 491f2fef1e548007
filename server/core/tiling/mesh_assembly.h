// AssembleServingMesh: the serving mesh (serving_mesh.h) of the global
// triangulation from the tiles' owned triangles, without a global CGAL
// triangulation.
//
// Vertices are SortedPoints' (already in the mesh's order). Each triangle
// is rotated so that its corner 0 has the smallest public id; triangles are
// ordered by the Hilbert key of their centroid (ServingMesh::CentroidKey),
// ties by their corners' public ids; neighbours within a tile come from
// its triangulation, across tiles from matching the open edges by their
// ends; the edges left open are the hull, whose ring starts at the edge
// ending at the hull vertex with the smallest public id and runs as
// ServingMesh's does (each edge ends where the one before it starts). So
// the mesh depends only on the points, never on the tiles or threads.
//
// Before it returns a mesh it checks what a consistent triangulation of
// the points must satisfy: every interior edge shared by exactly two
// triangles running opposite ways, the hull one closed ring, and Euler's
// formula (2V - F - H = 2 for V vertices, F triangles, H hull edges).
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_TILING_MESH_ASSEMBLY_H_
#define LOCATOR_CORE_TILING_MESH_ASSEMBLY_H_

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "locator/status.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/tiling/cells/sorted_points.h"
#include "server/core/tiling/tile_triangulation.h"

namespace locator {

// Builds the mesh from `sorted` (its vertex arrays are moved into the
// mesh) and the tiles' triangles (freed as they are copied), on `threads`
// threads; values (empty, or one per input point) give each vertex the
// value of its id; `digest` is the mesh's digest (VertexDigestOf).
// InvalidArgument if the mesh would exceed ServingMesh::kMaxElements
// triangles; Internal, naming the violation, if the triangles are not a
// consistent triangulation (a bug, never a wrong mesh).
Status AssembleServingMesh(SortedPoints* sorted,
                           std::vector<TileTriangles>* tiles,
                           std::span<const double> values, uint64_t digest,
                           unsigned threads,
                           std::shared_ptr<const ServingMesh>* out);

// Triangulation::VertexDigest() of a plain point set: XXH3 over the
// (id, x, y) of each distinct point, in id order; `ids` are the distinct
// points' ids (any order) among the input's indices.
uint64_t VertexDigestOf(std::span<const Point2> input,
                        std::span<const uint32_t> ids);

// The step of VertexDigestOf for input points [first, first + size) given
// as `points` (a chunk, for the out-of-core build): feeds the id, x and y
// of each whose distinct[id] is set to *hash.
void AddDistinctVertices(std::span<const Point2> points, uint64_t first,
                         const std::vector<bool>& distinct, Xxh3Digest* hash);

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_MESH_ASSEMBLY_H_
