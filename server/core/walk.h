// The visibility walk: from a start triangle, step across any edge that has
// the query strictly on its far side, until no such edge is left.
//
// Every side test is CGAL's exact orientation_2, so the answer is exact,
// including points on edges and vertices. The walk remembers the edge it
// entered through (never re-tests it: the query is known to be strictly on
// its near side) and tests the other edges in a random order; randomisation
// guarantees termination in any triangulation (Devillers, Pion & Teillaud,
// "Walking in a triangulation"), Delaunay or not.
//
// Thread-safety: stateless apart from a thread-local random generator.

#ifndef LOCATOR_CORE_WALK_H_
#define LOCATOR_CORE_WALK_H_

#include <cstdint>

#include "common/geometry.h"
#include "server/core/locate_result.h"
#include "server/core/triangulation.h"

namespace locator {

struct WalkOutcome {
  // The finite face where the walk ended. For kOutsideConvexHull, the hull
  // face the walk left through.
  Triangulation::Face_handle face;
  LocationType type = LocationType::kFace;
  // Edge index (kEdge, kOutsideConvexHull: the hull edge crossed) or vertex
  // index (kVertex) in `face`; -1 for kFace.
  int feature = -1;
  uint32_t faces_visited = 0;
};

// Walks from the finite face `start` to q. Precondition: IsFinite(q).
WalkOutcome Walk(const Triangulation& t, Triangulation::Face_handle start,
                 const Point2& q);

// Walks from `start` and fills the complete answer: for points outside the
// hull it reports the nearest hull edge that sees q. Sets
// result->cost.faces_visited; leaves the other cost fields untouched.
void WalkAndDescribe(const Triangulation& t, Triangulation::Face_handle start,
                     const Point2& q, LocateResult* result);

// A finite face whose closed triangle contains q, or for q outside the hull
// the hull face nearest to it: a good start for queries near q. Used when
// building start tables and samples.
Triangulation::Face_handle FaceNear(const Triangulation& t,
                                    Triangulation::Face_handle hint,
                                    const Point2& q);

}  // namespace locator

#endif  // LOCATOR_CORE_WALK_H_
