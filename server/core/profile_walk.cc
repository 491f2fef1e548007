#include "server/core/profile_walk.h"

#include <algorithm>
#include <string>
#include <utility>

#include "common/str_cat.h"

namespace locator {

namespace {

using Face_handle = Triangulation::Face_handle;
using Vertex_handle = Triangulation::Vertex_handle;
using CgalPoint = Triangulation::CgalPoint;

double Cross(const Point2& o, const Point2& u, const Point2& v) {
  return (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
}

// One segment's walk: a state machine over "in face" and "at vertex", every
// decision an exact orientation against p and q.
class SegmentWalker {
 public:
  SegmentWalker(const Triangulation& t, const Point2& p, const Point2& q,
                uint64_t max_faces, uint64_t* faces, SegmentTrace* out)
      : t_(t),
        p_(p),
        q_(q),
        cp_(Triangulation::ToCgal(p)),
        cq_(Triangulation::ToCgal(q)),
        direction_(CGAL::compare_xy(cp_, cq_)),
        max_faces_(max_faces),
        faces_(faces),
        out_(out) {}

  Status Run(const WalkOutcome& at) {
    face_ = at.face;
    out_->end_face = at.face;
    Status s;
    switch (at.type) {
      case LocationType::kVertex:
        vertex_ = at.face->vertex(at.feature);
        state_ = State::kAtVertex;
        break;
      case LocationType::kOutsideConvexHull:
        s = EnterHull();
        break;
      default:
        state_ = State::kInFace;
        break;
    }
    while (s.ok() && state_ != State::kDone) {
      s = state_ == State::kInFace ? StepInFace() : StepAtVertex();
    }
    return s;
  }

 private:
  enum class State { kInFace, kAtVertex, kDone };

  CGAL::Orientation Side(Vertex_handle v) const {
    return CGAL::orientation(cp_, cq_, v->point());
  }
  // Whether w (on the line) is strictly ahead of `from` along p->q.
  bool Ahead(const CgalPoint& from, Vertex_handle w) const {
    return CGAL::compare_xy(from, w->point()) == direction_;
  }
  bool ContainsQ(Face_handle f) const {
    for (int i = 0; i < 3; ++i) {
      if (CGAL::orientation(f->vertex(Ccw(i))->point(),
                            f->vertex(Cw(i))->point(), cq_) == CGAL::NEGATIVE) {
        return false;
      }
    }
    return true;
  }

  ProfileRegion FaceRegion(Face_handle f) const {
    if (t_.InDomain(f)) return {f, LocationType::kFace};
    return {Face_handle(), LocationType::kOutsideDomain};
  }
  // Along the finite edge (f, i): defined if a face on either side is.
  ProfileRegion EdgeRegion(Face_handle f, int i) const {
    const Face_handle g = f->neighbor(i);
    if (!t_.InDomain(f) && !t_.IsInfinite(g) && t_.InDomain(g)) {
      return {g, LocationType::kFace};
    }
    return FaceRegion(f);
  }

  Status Enter(Face_handle f) {
    face_ = f;
    out_->end_face = f;
    if (++*faces_ > max_faces_) return TooManyFaces(max_faces_);
    return Status::OK();
  }
  void Finish(const ProfileRegion& last) {
    out_->last = last;
    state_ = State::kDone;
  }
  void LeaveHull() {
    Finish({Face_handle(), LocationType::kOutsideConvexHull});
  }
  void Stop(const ProfileRegion& before, ProfilePointKind kind,
            const Point2& point) {
    const double dx = q_.x - p_.x;
    const double dy = q_.y - p_.y;
    const double t =
        ((point.x - p_.x) * dx + (point.y - p_.y) * dy) / (dx * dx + dy * dy);
    out_->stops.push_back({before, kind, point, std::clamp(t, 0.0, 1.0)});
  }
  void StopAtVertex(const ProfileRegion& before, Vertex_handle v) {
    Stop(before, ProfilePointKind::kMeshVertex,
         Triangulation::FromCgal(v->point()));
    vertex_ = v;
    state_ = State::kAtVertex;
  }
  // Where the line crosses the edge (a, b), rounded.
  void StopOnEdge(const ProfileRegion& before, Vertex_handle a,
                  Vertex_handle b) {
    const Point2 pa = Triangulation::FromCgal(a->point());
    const Point2 pb = Triangulation::FromCgal(b->point());
    const double oa = Cross(p_, q_, pa);
    const double ob = Cross(p_, q_, pb);
    const double s = oa == ob ? 0.5 : std::clamp(oa / (oa - ob), 0.0, 1.0);
    Stop(before, ProfilePointKind::kEdgeCrossing,
         {pa.x + s * (pb.x - pa.x), pa.y + s * (pb.y - pa.y)});
  }
  // Crosses edge i of face_ (already recorded, if at all) into its
  // neighbour.
  Status CrossEdge(int i) {
    const Face_handle next = face_->neighbor(i);
    if (t_.IsInfinite(next)) {
      LeaveHull();
      return Status::OK();
    }
    state_ = State::kInFace;
    return Enter(next);
  }

  // p is outside the hull: find the hull edge or vertex the segment enters
  // by, if any.
  Status EnterHull() {
    const auto& dt = t_.cgal();
    auto fc = dt.incident_faces(dt.infinite_vertex());
    const auto done = fc;
    do {
      const int k = fc->index(dt.infinite_vertex());
      const Face_handle f = fc->neighbor(k);
      const int i = dt.mirror_index(fc, k);
      const Vertex_handle a = f->vertex(Ccw(i));
      const Vertex_handle b = f->vertex(Cw(i));
      const CGAL::Orientation oa = Side(a);
      const CGAL::Orientation ob = Side(b);
      if (oa == CGAL::NEGATIVE || ob == CGAL::POSITIVE ||
          (oa == CGAL::ZERO && ob == CGAL::ZERO) ||
          CGAL::orientation(a->point(), b->point(), cp_) != CGAL::NEGATIVE) {
        continue;
      }
      const CGAL::Orientation side_q =
          CGAL::orientation(a->point(), b->point(), cq_);
      if (side_q == CGAL::NEGATIVE) continue;
      out_->end_face = f;
      if (side_q == CGAL::ZERO) break;  // it reaches the hull at q
      const ProfileRegion outside{Face_handle(),
                                  LocationType::kOutsideConvexHull};
      if (oa == CGAL::ZERO || ob == CGAL::ZERO) {
        StopAtVertex(outside, oa == CGAL::ZERO ? a : b);
        return Status::OK();
      }
      StopOnEdge(outside, a, b);
      state_ = State::kInFace;
      return Enter(f);
    } while (++fc != done);
    LeaveHull();
    return Status::OK();
  }

  Status StepInFace() {
    const Face_handle f = face_;
    CGAL::Orientation o[3];
    for (int i = 0; i < 3; ++i) o[i] = Side(f->vertex(i));
    int along = -1;  // the edge the line runs along, if any
    for (int k = 0; k < 3; ++k) {
      if (o[Ccw(k)] == CGAL::ZERO && o[Cw(k)] == CGAL::ZERO) along = k;
    }
    const ProfileRegion region =
        along >= 0 ? EdgeRegion(f, along) : FaceRegion(f);
    if (ContainsQ(f)) {
      Finish(region);
      return Status::OK();
    }
    if (along >= 0) {
      const Vertex_handle a = f->vertex(Ccw(along));
      StopAtVertex(region, Ahead(cp_, a) ? a : f->vertex(Cw(along)));
      return Status::OK();
    }
    for (int k = 0; k < 3; ++k) {
      const Vertex_handle a = f->vertex(Ccw(k));
      const Vertex_handle b = f->vertex(Cw(k));
      if (o[Ccw(k)] != CGAL::NEGATIVE || o[Cw(k)] != CGAL::POSITIVE) continue;
      // An exit edge through p is crossed at p: no stop of its own.
      if (CGAL::orientation(a->point(), b->point(), cp_) != CGAL::ZERO) {
        StopOnEdge(region, a, b);
      }
      return CrossEdge(k);
    }
    for (int k = 0; k < 3; ++k) {
      if (o[k] == CGAL::ZERO && Ahead(cp_, f->vertex(k))) {
        StopAtVertex(region, f->vertex(k));
        return Status::OK();
      }
    }
    return Status::Internal("profile: the walk lost the line in a face");
  }

  Status StepAtVertex() {
    const Vertex_handle v = vertex_;
    const auto& dt = t_.cgal();
    auto fc = dt.incident_faces(v);
    const auto done = fc;
    do {
      if (t_.IsInfinite(fc)) continue;
      const Face_handle f = fc;
      const int iv = f->index(v);
      const Vertex_handle a = f->vertex(Ccw(iv));
      const Vertex_handle b = f->vertex(Cw(iv));
      const CGAL::Orientation oa = Side(a);
      const CGAL::Orientation ob = Side(b);
      out_->end_face = f;
      if (oa == CGAL::NEGATIVE && ob == CGAL::POSITIVE) {
        Status s = Enter(f);
        if (!s.ok()) return s;
        const ProfileRegion region = FaceRegion(f);
        if (ContainsQ(f)) {
          Finish(region);
          return Status::OK();
        }
        StopOnEdge(region, a, b);
        return CrossEdge(iv);
      }
      // Along edge (v, a) (opposite b) or (v, b) (opposite a).
      for (const auto& [w, edge] :
           {std::pair{a, Cw(iv)}, std::pair{b, Ccw(iv)}}) {
        if (Side(w) != CGAL::ZERO || !Ahead(v->point(), w)) continue;
        const ProfileRegion region = EdgeRegion(f, edge);
        if (ContainsQ(f)) {
          Finish(region);
        } else {
          StopAtVertex(region, w);
        }
        return Status::OK();
      }
    } while (++fc != done);
    LeaveHull();
    return Status::OK();
  }

  const Triangulation& t_;
  const Point2 p_;
  const Point2 q_;
  const CgalPoint cp_;
  const CgalPoint cq_;
  // compare_xy(p, q): which way "ahead" is, lexicographically.
  const CGAL::Comparison_result direction_;
  const uint64_t max_faces_;
  uint64_t* const faces_;
  SegmentTrace* const out_;
  State state_ = State::kDone;
  Face_handle face_;
  Vertex_handle vertex_;
};

}  // namespace

Face_handle ClosedDomainFace(const Triangulation& t, const WalkOutcome& at) {
  switch (at.type) {
    case LocationType::kFace:
      break;
    case LocationType::kEdge: {
      const Face_handle g = at.face->neighbor(at.feature);
      if (!t.InDomain(at.face) && !t.IsInfinite(g) && t.InDomain(g)) return g;
      break;
    }
    case LocationType::kVertex: {
      auto fc = t.cgal().incident_faces(at.face->vertex(at.feature));
      const auto done = fc;
      do {
        if (!t.IsInfinite(fc) && t.InDomain(fc)) return fc;
      } while (++fc != done);
      return Face_handle();
    }
    default:
      return Face_handle();
  }
  return t.InDomain(at.face) ? at.face : Face_handle();
}

Status WalkSegment(const Triangulation& t, const WalkOutcome& at,
                   const Point2& p, const Point2& q, uint64_t max_faces,
                   uint64_t* faces, SegmentTrace* out) {
  return SegmentWalker(t, p, q, max_faces, faces, out).Run(at);
}

Status TooManyFaces(uint64_t max_faces) {
  return Status::ResourceExhausted(
      StrCat({"profile: the line crosses more than ", std::to_string(max_faces),
              " triangle edges, the limit per request"}));
}

}  // namespace locator
