// The straight-line walk behind TraceProfile (profile.h): what one segment
// of the line meets, traced exactly on the serving mesh. Internal to
// profile_trace.cc.
//
// Thread-safety: pure functions over an immutable ServingMesh.

#ifndef LOCATOR_CORE_PROFILE_WALK_H_
#define LOCATOR_CORE_PROFILE_WALK_H_

#include <cstdint>
#include <vector>

#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/profile.h"
#include "locator/status.h"
#include "server/core/mesh/mesh_walk.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

// What the surface is along one stretch of the line between two stops.
struct ProfileRegion {
  // An in-domain face the stretch runs through or along;
  // ServingMesh::kNoFace in a gap.
  uint32_t face = ServingMesh::kNoFace;
  // kFace where the surface is defined, else kOutsideDomain or
  // kOutsideConvexHull.
  LocationType type = LocationType::kFace;
};

// An edge crossing or mesh vertex on a segment, with the stretch before it.
struct SegmentStop {
  ProfileRegion before;
  ProfilePointKind kind = ProfilePointKind::kEdgeCrossing;
  Point2 point;
  // Fraction of the segment p->q at the stop, in [0, 1].
  double t = 0;
};

struct SegmentTrace {
  // In order from p to q; never at p or q themselves.
  std::vector<SegmentStop> stops;
  // The stretch from the last stop (or p) to q.
  ProfileRegion last;
  // A face at or near q: a hint for the walk to the next segment.
  uint32_t end_face = 0;
};

// Traces the segment p->q (p != q) from `at`, Walk()'s answer for p. Adds
// the faces it enters to *faces; ResourceExhausted once that passes
// max_faces.
[[nodiscard]] Status WalkSegment(const ServingMesh& mesh,
                                 const MeshWalkOutcome& at, const Point2& p,
                                 const Point2& q, uint64_t max_faces,
                                 uint64_t* faces, SegmentTrace* out);

// The ResourceExhausted status for a line entering more than max_faces.
Status TooManyFaces(uint64_t max_faces);

}  // namespace locator

#endif  // LOCATOR_CORE_PROFILE_WALK_H_
