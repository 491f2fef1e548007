// Walk: the visibility walk (visibility_walk.h) on CGAL's triangulation,
// for the code that still works on CGAL faces (profiles, natural neighbour
// coordinates, rasters) and for tests. Locates run on the serving mesh
// (mesh_walk.h).
//
// Thread-safety: stateless apart from a thread-local random generator.

#ifndef LOCATOR_CORE_WALK_H_
#define LOCATOR_CORE_WALK_H_

#include "common/geometry.h"
#include "server/core/triangulation.h"
#include "server/core/visibility_walk.h"

namespace locator {

// For kOutsideConvexHull, `face` is the finite hull face the walk left.
using WalkOutcome = BasicWalkOutcome<Triangulation::Face_handle>;

// Walks from the finite face `start` to q. Precondition: IsFinite(q).
WalkOutcome Walk(const Triangulation& t, Triangulation::Face_handle start,
                 const Point2& q);

}  // namespace locator

#endif  // LOCATOR_CORE_WALK_H_
