// The walk on the serving mesh (first by the orientation filter alone, then
// the exact visibility walk of visibility_walk.h), and the complete answer
// it gives: what every strategy, profile, raster and start table runs once
// it has a start.
//
// Thread-safety: stateless apart from a thread-local random generator.

#ifndef LOCATOR_CORE_MESH_WALK_H_
#define LOCATOR_CORE_MESH_WALK_H_

#include <array>
#include <cstdint>

#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "server/core/cgal/orientation.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/mesh/visibility_walk.h"

namespace locator {

// For kOutsideConvexHull, `face` is the hull face the walk left.
using MeshWalkOutcome = BasicWalkOutcome<uint32_t>;

// Walks from face `start` to q: first by the orientation filter alone
// (ClearWalk, up to 16 faces) while the filter decides, then by the exact
// visibility walk from where that stopped. Precondition: IsFinite(q).
MeshWalkOutcome Walk(const ServingMesh& mesh, uint32_t start, const Point2& q);

// The orientation filters of q against the edges of a triangle (a, b, c),
// counter-clockwise: edge[i] is the edge opposite corner i.
struct FaceFilters {
  FaceFilters(const Point2& a, const Point2& b, const Point2& c,
              const Point2& q)
      : edge{{{b, c, q}, {c, a, q}, {a, b, q}}} {}

  // True only when q is in the triangle's interior. (All three filters
  // are read, without a branch between them.)
  bool ClearlyInside() const {
    return (int{edge[0].ClearlyLeft()} & int{edge[1].ClearlyLeft()} &
            int{edge[2].ClearlyLeft()}) != 0;
  }
  // The first edge that q is clearly beyond (outside it), or -1.
  int ClearExit() const {
    return edge[0].ClearlyRight()   ? 0
           : edge[1].ClearlyRight() ? 1
           : edge[2].ClearlyRight() ? 2
                                    : -1;
  }

  std::array<OrientationFilter, 3> edge;
};

// Walks from walk->face toward q by the orientation filter alone, for at
// most `max_steps` steps, each across an edge that q is clearly beyond,
// counting the faces it tests in walk->faces_visited. True when it decided,
// with *walk an answer the exact walk gives too: kFace at a face whose
// interior clearly holds q, or kOutsideConvexHull across a hull edge that q
// is clearly beyond. False when a test is undecided (q on or next to an
// edge) or the steps run out: then walk->face is where it stopped, a good
// start for the exact walk. A scan's next point is most often in or next
// to its last point's face, and this walk draws no random order and
// branches into no exact predicate.
inline bool ClearWalk(const ServingMesh& mesh, const Point2& q, int max_steps,
                      MeshWalkOutcome* walk) {
  for (int step = 0;; ++step) {
    const uint32_t f = walk->face;
    ++walk->faces_visited;
    const FaceFilters filters(mesh.CornerPoint(f, 0), mesh.CornerPoint(f, 1),
                              mesh.CornerPoint(f, 2), q);
    if (filters.ClearlyInside()) {
      walk->type = LocationType::kFace;
      walk->feature = -1;
      return true;
    }
    if (step == max_steps) return false;
    const int exit = filters.ClearExit();
    if (exit < 0) return false;
    const uint32_t next = mesh.Neighbor(f, exit);
    if (ServingMesh::IsHull(next)) {
      walk->type = LocationType::kOutsideConvexHull;
      walk->feature = exit;
      return true;
    }
    walk->face = next;
  }
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
