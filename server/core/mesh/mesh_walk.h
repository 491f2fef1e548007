// The visibility walk (visibility_walk.h) on the serving mesh, and the
// complete answer it gives: what every strategy runs once it has a start.
//
// Thread-safety: stateless apart from a thread-local random generator.

#ifndef LOCATOR_CORE_MESH_WALK_H_
#define LOCATOR_CORE_MESH_WALK_H_

#include <cstdint>

#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/mesh/visibility_walk.h"

namespace locator {

// For kOutsideConvexHull, `face` is the hull face the walk left.
using MeshWalkOutcome = BasicWalkOutcome<uint32_t>;

// Walks from face `start` to q. Precondition: IsFinite(q).
MeshWalkOutcome Walk(const ServingMesh& mesh, uint32_t start, const Point2& q);

// True only when q is strictly inside face f, decided by the orientation
// filter alone: then Walk(mesh, f, q) ends at f with kFace at its first
// face. A scan's next point is most often in its last point's face, and
// this test draws no random order and branches into no exact predicate.
inline bool ClearlyInside(const ServingMesh& mesh, uint32_t f,
                          const Point2& q) {
  const Point2& a = mesh.CornerPoint(f, 0);
  const Point2& b = mesh.CornerPoint(f, 1);
  const Point2& c = mesh.CornerPoint(f, 2);
  return ClearlyLeft(b, c, q) & ClearlyLeft(c, a, q) & ClearlyLeft(a, b, q);
}

// Walks from `start` and fills the complete answer: for points outside the
// hull it reports the nearest hull edge that sees q. Sets
// result->cost.faces_visited; leaves the other cost fields untouched.
// Returns the face the answer names (for kOutsideDomain, the face where the
// walk ended): a good start for the next query near q.
uint32_t WalkAndDescribe(const ServingMesh& mesh, uint32_t start,
                         const Point2& q, LocateResult* result,
                         Detail detail = Detail::kFull);

// An in-domain face whose closed triangle contains the point Walk() located
// at `at` (a point on the domain's boundary edge or vertex takes the
// in-domain side); ServingMesh::kNoFace outside the hull or the closed
// domain.
uint32_t ClosedDomainFace(const ServingMesh& mesh, const MeshWalkOutcome& at);

// A face whose closed triangle contains q, or for q outside the hull the
// hull face the walk left through: a good start for queries near q.
inline uint32_t FaceNear(const ServingMesh& mesh, uint32_t hint,
                         const Point2& q) {
  return Walk(mesh, hint, q).face;
}

}  // namespace locator

#endif  // LOCATOR_CORE_MESH_WALK_H_
