// The canonical Delaunay triangulation: the one triangulation of a point
// set that every build in locator produces, whatever the insertion order,
// the tiles or the threads, so that tiles and a global build agree triangle
// for triangle where points are co-circular (every square of a DEM's grid).
//
// The tie-break is a symbolic perturbation of the lifting map (Devillers
// and Teillaud's, which CGAL uses): point p is lifted to
// |p|^2 + eps^(n - rank(p)), rank in lexicographic (x, y) order, so the
// lexicographically largest point of four co-circular ones is lifted the
// most. Then no four points are co-circular: InCanonicalCircle() decides
// every case, and the Delaunay triangulation of the perturbed lifting (its
// regular triangulation) is unique. It is a Delaunay triangulation of the
// unperturbed points too: the perturbation only decides ties.
//
// Why CGAL builds it. CGAL's Delaunay_triangulation_2 and
// Constrained_Delaunay_triangulation_2 insert a point and then flip every
// edge that fails side_of_oriented_circle(..., perturb = true) (CGAL 5.5,
// Delaunay_triangulation_2.h propagating_flip and
// Constrained_Delaunay_triangulation_2.h is_flipable): this predicate. For
// a generic lifting, incremental insertion with Lawson flips yields the
// regular triangulation of the points inserted so far (Edelsbrunner and
// Shah, 1996), so CGAL's result is this unique triangulation whatever the
// order of insertion, and no flip pass is needed after it. The tests check
// it independently with CountNonCanonicalEdges() on co-circular inputs in
// many insertion orders.
//
// Why tiles may use it. A triangle of the canonical triangulation of a
// subset S of the points is a triangle of the canonical triangulation of
// all points iff no point is perturbed-inside its circle; only points on
// or inside the closed circumdisk can be, so it suffices that every point
// in the closed circumdisk is in S (halo_cells.h).
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_TILING_CANONICAL_DELAUNAY_H_
#define LOCATOR_CORE_TILING_CANONICAL_DELAUNAY_H_

#include <cstddef>

#include "locator/geometry.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

// Whether d is inside the circle through the counter-clockwise triangle
// a, b, c under the perturbation (exactly; never undecided): the exact
// in-circle sign, and for co-circular points the sign of the leading
// perturbation term. Precondition: a, b, c not collinear; d distinct from
// them.
bool InCanonicalCircle(const Point2& a, const Point2& b, const Point2& c,
                       const Point2& d);

// The number of violations of the canonical Delaunay property in `mesh`:
// interior edges whose opposite vertex lies InCanonicalCircle of the other
// triangle, and reflex turns of the hull ring. A mesh of every point as a
// vertex whose triangles tile a region has none iff it is the canonical
// Delaunay triangulation (local Delaunay everywhere and a convex boundary
// give the regular triangulation of a generic lifting).
size_t CountNonCanonicalEdges(const ServingMesh& mesh);

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_CANONICAL_DELAUNAY_H_
