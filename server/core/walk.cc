#include "server/core/walk.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "server/core/fast_random.h"
#include "server/core/segment_distance.h"

namespace locator {

namespace {

using Face_handle = Triangulation::Face_handle;

CGAL::Orientation SideOf(Face_handle f, int i,
                         const Triangulation::CgalPoint& q) {
  return CGAL::orientation(f->vertex(Ccw(i))->point(),
                           f->vertex(Cw(i))->point(), q);
}

// Among the hull edges that see q (a contiguous chain containing the exit
// edge), finds the nearest one; ties go to the edge with the smaller vertex
// ids, so the answer does not depend on where the walk left the hull. Walks
// the chain both ways around the infinite vertex. Returns the finite face and
// edge index of that edge.
void NearestVisibleHullEdge(const Triangulation& t, Face_handle* face,
                            int* edge, const Point2& q) {
  const auto& dt = t.cgal();
  const auto cq = Triangulation::ToCgal(q);
  struct Candidate {
    long double distance;
    std::pair<int64_t, int64_t> ids;  // (smaller, larger) vertex id
    bool operator<(const Candidate& o) const {
      return distance < o.distance || (distance == o.distance && ids < o.ids);
    }
  };
  const auto candidate = [&](Face_handle f, int i) {
    const auto a = f->vertex(Ccw(i));
    const auto b = f->vertex(Cw(i));
    return Candidate{SegmentDistance2(Triangulation::FromCgal(a->point()),
                                      Triangulation::FromCgal(b->point()), q),
                     std::minmax(a->info().id, b->info().id)};
  };
  const Face_handle exit_inf = (*face)->neighbor(*edge);
  Candidate best = candidate(*face, *edge);
  for (int direction = 0; direction < 2; ++direction) {
    auto fc = dt.incident_faces(dt.infinite_vertex(), exit_inf);
    for (;;) {
      if (direction == 0) {
        ++fc;
      } else {
        --fc;
      }
      if (fc == exit_inf) break;  // the whole hull sees q
      const int k = fc->index(dt.infinite_vertex());
      const Face_handle f = fc->neighbor(k);
      const int i = dt.mirror_index(fc, k);
      if (SideOf(f, i, cq) != CGAL::RIGHT_TURN) break;
      const Candidate c = candidate(f, i);
      if (c < best) {
        best = c;
        *face = f;
        *edge = i;
      }
    }
  }
}

}  // namespace

WalkOutcome Walk(const Triangulation& t, Face_handle start, const Point2& q) {
  const auto cq = Triangulation::ToCgal(q);
  WalkOutcome out;
  Face_handle f = start;
  int entry = -1;
  for (;;) {
    ++out.faces_visited;
    // The entry edge is known to be POSITIVE; the others are tested in a
    // random order and the walk leaves through the first NEGATIVE one.
    CGAL::Orientation side[3] = {CGAL::POSITIVE, CGAL::POSITIVE,
                                 CGAL::POSITIVE};
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
      side[i] = SideOf(f, i, cq);
      if (side[i] == CGAL::NEGATIVE) {
        leave = i;
        break;
      }
    }
    if (leave >= 0) {
      const Face_handle next = f->neighbor(leave);
      if (t.IsInfinite(next)) {
        out.face = f;
        out.type = LocationType::kOutsideConvexHull;
        out.feature = leave;
        return out;
      }
      entry = next->index(f);
      f = next;
      continue;
    }
    out.face = f;
    int zeros = 0;
    int zero_index[2] = {-1, -1};
    for (int i = 0; i < 3; ++i) {
      if (side[i] == CGAL::COLLINEAR) zero_index[zeros++] = i;
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

void WalkAndDescribe(const Triangulation& t, Face_handle start, const Point2& q,
                     LocateResult* result) {
  WalkOutcome w = Walk(t, start, q);
  if (w.type == LocationType::kOutsideConvexHull) {
    NearestVisibleHullEdge(t, &w.face, &w.feature, q);
  }
  t.Describe(w.face, w.type, w.feature, q, result);
  result->cost.faces_visited = w.faces_visited;
}

Face_handle FaceNear(const Triangulation& t, Face_handle hint,
                     const Point2& q) {
  return Walk(t, hint, q).face;
}

}  // namespace locator
