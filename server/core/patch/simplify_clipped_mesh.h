// SimplifyClippedMesh: a ClippedMesh with fewer vertices whose surface is
// within a vertical tolerance of the original at every original vertex,
// for the coarser levels of a terrain pyramid.
//
// The footprint stays exactly the same: every vertex on the footprint's
// boundary inside the box (the TIN's hull or domain boundary) is kept.
// Vertices on the box's sides are thinned by a rule that depends only on
// the side's own vertices (Douglas-Peucker along the side, within the
// tolerance), so that two boxes sharing a side keep the same vertices on
// it and still meet without cracks. The interior is refined greedily
// (Garland and Heckbert's insertion): starting from the kept boundary in a
// constrained Delaunay triangulation (CGAL), the vertex farthest, in
// height, from the current surface is inserted until none is farther than
// the tolerance.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_PATCH_SIMPLIFY_CLIPPED_MESH_H_
#define LOCATOR_CORE_PATCH_SIMPLIFY_CLIPPED_MESH_H_

#include "server/core/patch/clipped_mesh.h"

namespace locator {

// `mesh` simplified within `tolerance` (in the heights' unit, >= 0), its
// Delaunay criterion taken with x scaled by `x_scale` (> 0: for longitudes
// and latitudes, the cosine of the latitude, so that triangles are well
// shaped on the ground). Returns `mesh` unchanged if its boundary edges
// cross (it was cut from no planar mesh), which CGAL refuses.
ClippedMesh SimplifyClippedMesh(const ClippedMesh& mesh, double tolerance,
                                double x_scale);

}  // namespace locator

#endif  // LOCATOR_CORE_PATCH_SIMPLIFY_CLIPPED_MESH_H_
