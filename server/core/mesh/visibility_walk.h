// VisibilityWalk: from a start triangle, step across any edge that has the
// query strictly on its far side, until no such edge is left, over any
// Topology; the serving mesh's is in mesh_walk.h (every locate, value,
// profile and raster).
//
// Every side test is CGAL's exact orientation_2, so the answer is exact,
// including points on edges and vertices. The walk remembers the edge it
// entered through (never re-tests it: the query is known to be strictly on
// its near side) and tests the other edges in a random order; randomisation
// guarantees termination in any triangulation (Devillers, Pion & Teillaud,
// "Walking in a triangulation"), Delaunay or not.
//
// A Topology provides, for its Face type:
//   Side SideOf(Face f, int i, const Point2& q)  q against edge i of f
//                                                (kLeft: f's side)
//   bool Next(Face f, int i, Face* next)         the face across edge i;
//                                                false beyond the hull
//   int EntryIndex(Face next, Face from)         the edge of next shared
//                                                with from
//   void Prefetch(Face f)                        a hint that the walk may
//                                                step from f to any of its
//                                                neighbours next
//
// Thread-safety: stateless apart from a thread-local random generator.

#ifndef LOCATOR_CORE_VISIBILITY_WALK_H_
#define LOCATOR_CORE_VISIBILITY_WALK_H_

#include <cstdint>

#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "server/core/cgal/orientation.h"
#include "server/core/geometry/fast_random.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

template <class Face>
struct BasicWalkOutcome {
  // The face where the walk ended. For kOutsideConvexHull, the hull face the
  // walk left through.
  Face face{};
  LocationType type = LocationType::kFace;
  // Edge index (kEdge, kOutsideConvexHull: the hull edge crossed) or vertex
  // index (kVertex) in `face`; -1 for kFace.
  int feature = -1;
  uint32_t faces_visited = 0;
};

// Walks from `start` to q. Precondition: IsFinite(q).
template <class Topology>
BasicWalkOutcome<typename Topology::Face> VisibilityWalk(
    const Topology& topology, typename Topology::Face start, const Point2& q) {
  using Face = typename Topology::Face;
  BasicWalkOutcome<Face> out;
  Face f = start;
  int entry = -1;
  for (;;) {
    ++out.faces_visited;
    topology.Prefetch(f);
    // The entry edge is known to be kLeft; the others are tested in a
    // random order and the walk leaves through the first kRight one.
    Side side[3] = {Side::kLeft, Side::kLeft, Side::kLeft};
    const uint64_t r = ThreadRandom();
    int candidates[3];
    int count;
    if (entry < 0) {
      const int first = static_cast<int>(r % 3);
      candidates[0] = first;
      candidates[1] = Ccw(first);
      candidates[2] = Cw(first);
      count = 3;
    } else {
      const bool swap = r & 1;
      candidates[0] = swap ? Cw(entry) : Ccw(entry);
      candidates[1] = swap ? Ccw(entry) : Cw(entry);
      count = 2;
    }
    int leave = -1;
    for (int c = 0; c < count; ++c) {
      const int i = candidates[c];
      side[i] = topology.SideOf(f, i, q);
      if (side[i] == Side::kRight) {
        leave = i;
        break;
      }
    }
    if (leave >= 0) {
      Face next;
      if (!topology.Next(f, leave, &next)) {
        out.face = f;
        out.type = LocationType::kOutsideConvexHull;
        out.feature = leave;
        return out;
      }
      entry = topology.EntryIndex(next, f);
      f = next;
      continue;
    }
    out.face = f;
    int zeros = 0;
    int zero_index[2] = {-1, -1};
    for (int i = 0; i < 3; ++i) {
      if (side[i] == Side::kOn) zero_index[zeros++] = i;
    }
    if (zeros == 0) {
      out.type = LocationType::kFace;
    } else if (zeros == 1) {
      out.type = LocationType::kEdge;
      out.feature = zero_index[0];
    } else {
      // On two edges: the corner they share.
      out.type = LocationType::kVertex;
      out.feature = 3 - zero_index[0] - zero_index[1];
    }
    return out;
  }
}

}  // namespace locator

#endif  // LOCATOR_CORE_VISIBILITY_WALK_H_
