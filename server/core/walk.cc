#include "server/core/walk.h"

#include <cstdint>

#include "server/core/fast_random.h"

namespace locator {

namespace {

using Face_handle = Triangulation::Face_handle;

int Ccw(int i) { return i == 2 ? 0 : i + 1; }
int Cw(int i) { return i == 0 ? 2 : i - 1; }

CGAL::Orientation SideOf(Face_handle f, int i,
                         const Triangulation::CgalPoint& q) {
  return CGAL::orientation(f->vertex(Ccw(i))->point(),
                           f->vertex(Cw(i))->point(), q);
}

// Squared distance from q to segment ab, in long double so that coordinates
// near 1e308 do not overflow.
long double SegmentDistance2(const Point2& a, const Point2& b,
                             const Point2& q) {
  const long double abx = b.x - static_cast<long double>(a.x);
  const long double aby = b.y - static_cast<long double>(a.y);
  const long double aqx = q.x - static_cast<long double>(a.x);
  const long double aqy = q.y - static_cast<long double>(a.y);
  const long double len2 = abx * abx + aby * aby;
  long double t = len2 > 0 ? (aqx * abx + aqy * aby) / len2 : 0;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  const long double dx = aqx - t * abx;
  const long double dy = aqy - t * aby;
  return dx * dx + dy * dy;
}

// Among the hull edges that see q (a contiguous chain containing the exit
// edge), finds the nearest one. Walks the chain both ways around the
// infinite vertex. Returns the finite face and edge index of that edge.
void NearestVisibleHullEdge(const Triangulation& t, Face_handle* face,
                            int* edge, const Point2& q) {
  const auto& dt = t.cgal();
  const auto cq = Triangulation::ToCgal(q);
  auto edge_of = [&](Face_handle inf_face, Face_handle* f, int* i) {
    const int k = inf_face->index(dt.infinite_vertex());
    *f = inf_face->neighbor(k);
    *i = dt.mirror_index(inf_face, k);
  };
  auto distance = [&](Face_handle f, int i) {
    return SegmentDistance2(Triangulation::FromCgal(f->vertex(Ccw(i))->point()),
                            Triangulation::FromCgal(f->vertex(Cw(i))->point()),
                            q);
  };
  const Face_handle exit_inf = (*face)->neighbor(*edge);
  long double best = distance(*face, *edge);
  for (int direction = 0; direction < 2; ++direction) {
    auto fc = dt.incident_faces(dt.infinite_vertex(), exit_inf);
    for (;;) {
      if (direction == 0)
        ++fc;
      else
        --fc;
      if (fc == exit_inf) break;  // the whole hull sees q
      Face_handle f;
      int i;
      edge_of(fc, &f, &i);
      if (SideOf(f, i, cq) != CGAL::RIGHT_TURN) break;
      const long double d = distance(f, i);
      if (d < best) {
        best = d;
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
