// The serving mesh of a dataset given as triangles (constraints.triangles
// and no other constraint: .ele, .off, the TINs of server/core/terrain/),
// built without Triangulation's constraint hierarchy, which costs ~10 us per
// mesh edge (seconds for a million triangles).
//
// The given triangles are the in-domain faces as they are. What fills the
// rest of the convex hull (the out-of-domain faces) comes from CGAL's
// constrained Delaunay triangulation of all the points with only the
// mesh's boundary edges (edges of one triangle) constrained. The mesh is
// checked as Triangulation::Build checks it, with its messages where the
// failure is the same: corner indices, repeated and collinear corners,
// edges of three triangles, repeated triangles; and overlaps. An overlap
// is found without testing triangle pairs: with every triangle
// counter-clockwise and every interior edge used once each way, the
// triangles cover a point as many times as the boundary winds around it,
// so they overlap nowhere if and only if the boundary edges cross nowhere
// (else CGAL adds a vertex) and, flooded from each boundary edge's sides
// across the unconstrained edges, the faces of that triangulation are
// each consistently inside (left of a boundary edge) or outside (right of
// one, or beyond the hull). A dataset point no triangle uses must lie
// outside; a point on a boundary edge splits it and is refused.
//
// The serving mesh is derived as BuildServingMesh derives it from CGAL's
// (the same vertex order and ids, Hilbert orders, constrained edges and
// digest), so that it answers as CGAL's locate on Triangulation::Build's
// triangulation of the same dataset: the in-domain faces are the same; the
// out-of-domain faces may split the same regions differently where points
// are co-circular, and triangle ids may differ where two centroids share a
// Hilbert cell.
//
// Thread-safety: free functions.

#ifndef LOCATOR_CORE_GIVEN_MESH_H_
#define LOCATOR_CORE_GIVEN_MESH_H_

#include "locator/dataset.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "server/core/mesh/mesh_file.h"

namespace locator {

// Whether `dataset` is a mesh given as triangles and nothing else
// constrains it.
bool IsGivenMesh(const Dataset& dataset);

// The serving mesh and facts of `dataset`, for which IsGivenMesh() holds.
// InvalidArgument naming what is wrong, as above.
StatusOr<BuiltMesh> BuildGivenMesh(const Dataset& dataset);

}  // namespace locator

#endif  // LOCATOR_CORE_GIVEN_MESH_H_
