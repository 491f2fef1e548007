// Profile: the surface along a polyline, traced exactly by a straight-line
// walk from triangle to triangle along each segment.
//
// Every point where a segment crosses a triangle edge is a breakpoint of the
// piecewise-linear surface, so consecutive breakpoints bound a stretch where
// the surface is linear along the line: the profile is exact. The walk
// decides which edge the line leaves a triangle by (and whether it passes
// exactly through a vertex, or runs along an edge) with CGAL's exact
// orientation_2 against the segment's endpoints; only the crossing points'
// coordinates are rounded. The work is O(triangles crossed) per segment,
// plus O(hull edges) for a segment that starts outside the hull.
//
// Breakpoints are reported where the surface is defined on at least one
// side: edges between two out-of-domain faces (inside a hole) and the
// infinite faces outside the hull are walked through silently, as gaps.
//
// The plain types of a profile; profile_trace.h traces one.

#ifndef LOCATOR_PROFILE_H_
#define LOCATOR_PROFILE_H_

#include <cstdint>
#include <vector>

#include "locator/geometry.h"
#include "locator/interpolation.h"
#include "locator/locate_result.h"

namespace locator {

enum class ProfilePointKind : uint8_t {
  kLineVertex = 0,    // a vertex of the requested polyline
  kEdgeCrossing = 1,  // the line crosses a triangle edge
  kMeshVertex = 2,    // the line passes exactly through a mesh vertex
  kSample = 3,        // one of the evenly spaced samples
};

struct ProfilePoint {
  ProfilePointKind kind = ProfilePointKind::kLineVertex;
  Point2 point;
  // Distance from the line's first vertex along the line.
  double distance = 0;
  // Index of the segment it lies on (a vertex between two segments belongs
  // to the later one; the line's last vertex to the last segment).
  uint32_t segment = 0;
  bool has_value = false;
  double value = 0;
  // The in-domain triangle the line runs through after this point (for the
  // last point, the one it ends in); -1 where a gap begins or the line ends
  // outside the hull or the domain.
  int64_t triangle_id = -1;
};

struct ProfileGap {
  double from_distance = 0;
  double to_distance = 0;
  // kOutsideConvexHull or kOutsideDomain.
  LocationType reason = LocationType::kOutsideConvexHull;
};

struct Profile {
  // Line vertices, edge crossings and mesh vertices, in order along the
  // line (non-decreasing distance).
  std::vector<ProfilePoint> breakpoints;
  // The requested samples, in order along the line.
  std::vector<ProfilePoint> samples;
  // Stretches outside the hull or the domain, in order; adjacent stretches
  // of the same reason are merged.
  std::vector<ProfileGap> gaps;
  double length = 0;
  // kEdgeCrossing plus kMeshVertex breakpoints.
  uint64_t crossings = 0;
};

struct ProfileOptions {
  // Evenly spaced samples over the whole line (first and last vertex
  // included when >= 2); 0: none.
  uint32_t samples = 0;
  // The most faces the walk may enter over the whole line (holes and all);
  // beyond it the trace stops with ResourceExhausted.
  uint64_t max_faces = 1'000'000;
  Interpolation interpolation = Interpolation::kLinear;
};

}  // namespace locator

#endif  // LOCATOR_PROFILE_H_
