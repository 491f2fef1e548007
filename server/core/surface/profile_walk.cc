#include "server/core/surface/profile_walk.h"

#include <algorithm>
#include <string>
#include <utility>

#include "common/str_cat.h"
#include "server/core/cgal/orientation.h"
#include "server/core/geometry/segment_crossing.h"
#include "server/core/geometry/wide_math.h"

namespace locator {

namespace {

// -1, 0 or 1 as a is before, at or after b, lexicographically (x, then y):
// CGAL's compare_xy, exact on doubles.
int CompareXY(const Point2& a, const Point2& b) {
  if (a.x != b.x) return a.x < b.x ? -1 : 1;
  if (a.y != b.y) return a.y < b.y ? -1 : 1;
  return 0;
}

// One segment's walk: a state machine over "in face" and "at vertex", every
// decision an exact orientation against p and q.
class SegmentWalker {
 public:
  SegmentWalker(const ServingMesh& mesh, const Point2& p, const Point2& q,
                uint64_t max_faces, uint64_t* faces, SegmentTrace* out)
      : mesh_(mesh),
        p_(p),
        q_(q),
        direction_(CompareXY(p, q)),
        max_faces_(max_faces),
        faces_(faces),
        out_(out) {}

  Status Run(const MeshWalkOutcome& at) {
    face_ = at.face;
    out_->end_face = at.face;
    Status s;
    switch (at.type) {
      case LocationType::kVertex:
        vertex_ = mesh_.Corner(at.face, at.feature);
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

  const Point2& PointOf(uint32_t v) const { return mesh_.arrays().points[v]; }
  // Which side of the line p->q mesh vertex v is on.
  Side SideOf(uint32_t v) const { return Orientation(p_, q_, PointOf(v)); }
  // Whether mesh vertex w (on the line) is strictly ahead of `from` along
  // p->q.
  bool Ahead(const Point2& from, uint32_t w) const {
    return CompareXY(from, PointOf(w)) == direction_;
  }
  bool ContainsQ(uint32_t f) const {
    for (int i = 0; i < 3; ++i) {
      if (Orientation(mesh_.CornerPoint(f, Ccw(i)), mesh_.CornerPoint(f, Cw(i)),
                      q_) == Side::kRight) {
        return false;
      }
    }
    return true;
  }

  ProfileRegion FaceRegion(uint32_t f) const {
    if (mesh_.InDomain(f)) return {f, LocationType::kFace};
    return {ServingMesh::kNoFace, LocationType::kOutsideDomain};
  }
  // Along the edge (f, i): defined if a face on either side is.
  ProfileRegion EdgeRegion(uint32_t f, int i) const {
    const uint32_t g = mesh_.Neighbor(f, i);
    if (!mesh_.InDomain(f) && !ServingMesh::IsHull(g) && mesh_.InDomain(g)) {
      return {g, LocationType::kFace};
    }
    return FaceRegion(f);
  }

  Status Enter(uint32_t f) {
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
    Finish({ServingMesh::kNoFace, LocationType::kOutsideConvexHull});
  }
  // Stops at `point`, which is on the segment: its fraction comes from
  // projecting it. In Wide: the squares of coordinate differences overflow
  // a double beyond ~1e154 and underflow below ~1e-154.
  void Stop(const ProfileRegion& before, ProfilePointKind kind,
            const Point2& point) {
    const Wide dx = Wide{q_.x} - p_.x;
    const Wide dy = Wide{q_.y} - p_.y;
    const Wide t = ((Wide{point.x} - p_.x) * dx + (Wide{point.y} - p_.y) * dy) /
                   (dx * dx + dy * dy);
    out_->stops.push_back(
        {before, kind, point,
         static_cast<double>(std::clamp(t, Wide{0}, Wide{1}))});
  }
  // Stops at corner v of face f.
  void StopAtVertex(const ProfileRegion& before, uint32_t f, uint32_t v) {
    Stop(before, ProfilePointKind::kMeshVertex, PointOf(v));
    face_ = f;
    vertex_ = v;
    state_ = State::kAtVertex;
  }
  // Where the segment crosses the edge (a, b), rounded.
  void StopOnEdge(const ProfileRegion& before, uint32_t a, uint32_t b) {
    Stop(before, ProfilePointKind::kEdgeCrossing,
         SegmentCrossing(p_, q_, PointOf(a), PointOf(b)));
  }
  // Crosses edge i of face_ (already recorded, if at all) into its
  // neighbour.
  Status CrossEdge(int i) {
    const uint32_t next = mesh_.Neighbor(face_, i);
    if (ServingMesh::IsHull(next)) {
      LeaveHull();
      return Status::OK();
    }
    state_ = State::kInFace;
    return Enter(next);
  }

  // p is outside the hull: find the hull edge or vertex the segment enters
  // by, if any.
  Status EnterHull() {
    for (const uint32_t edge : mesh_.hull()) {
      const uint32_t f = ServingMesh::EdgeFace(edge);
      const int i = ServingMesh::EdgeIndex(edge);
      const uint32_t a = mesh_.Corner(f, Ccw(i));
      const uint32_t b = mesh_.Corner(f, Cw(i));
      const Side oa = SideOf(a);
      const Side ob = SideOf(b);
      if (oa == Side::kRight || ob == Side::kLeft ||
          (oa == Side::kOn && ob == Side::kOn) ||
          Orientation(PointOf(a), PointOf(b), p_) != Side::kRight) {
        continue;
      }
      const Side side_q = Orientation(PointOf(a), PointOf(b), q_);
      if (side_q == Side::kRight) continue;
      out_->end_face = f;
      if (side_q == Side::kOn) break;  // it reaches the hull at q
      const ProfileRegion outside{ServingMesh::kNoFace,
                                  LocationType::kOutsideConvexHull};
      if (oa == Side::kOn || ob == Side::kOn) {
        StopAtVertex(outside, f, oa == Side::kOn ? a : b);
        return Status::OK();
      }
      StopOnEdge(outside, a, b);
      state_ = State::kInFace;
      return Enter(f);
    }
    LeaveHull();
    return Status::OK();
  }

  Status StepInFace() {
    const uint32_t f = face_;
    Side o[3];
    for (int i = 0; i < 3; ++i) o[i] = SideOf(mesh_.Corner(f, i));
    int along = -1;  // the edge the line runs along, if any
    for (int k = 0; k < 3; ++k) {
      if (o[Ccw(k)] == Side::kOn && o[Cw(k)] == Side::kOn) along = k;
    }
    const ProfileRegion region =
        along >= 0 ? EdgeRegion(f, along) : FaceRegion(f);
    if (ContainsQ(f)) {
      Finish(region);
      return Status::OK();
    }
    if (along >= 0) {
      const uint32_t a = mesh_.Corner(f, Ccw(along));
      StopAtVertex(region, f, Ahead(p_, a) ? a : mesh_.Corner(f, Cw(along)));
      return Status::OK();
    }
    for (int k = 0; k < 3; ++k) {
      if (o[Ccw(k)] != Side::kRight || o[Cw(k)] != Side::kLeft) continue;
      // An exit edge through p is crossed at p: no stop of its own.
      if (Orientation(mesh_.CornerPoint(f, Ccw(k)), mesh_.CornerPoint(f, Cw(k)),
                      p_) != Side::kOn) {
        StopOnEdge(region, mesh_.Corner(f, Ccw(k)), mesh_.Corner(f, Cw(k)));
      }
      return CrossEdge(k);
    }
    for (int k = 0; k < 3; ++k) {
      if (o[k] == Side::kOn && Ahead(p_, mesh_.Corner(f, k))) {
        StopAtVertex(region, f, mesh_.Corner(f, k));
        return Status::OK();
      }
    }
    return Status::Internal("profile: the walk lost the line in a face");
  }

  // In face f around vertex_: the step if the line leaves vertex_ into f or
  // along one of f's edges at vertex_; false, with nothing done, otherwise.
  bool StepFromVertexInto(uint32_t f, Status* status) {
    const uint32_t v = vertex_;
    const int iv = mesh_.IndexOf(f, v);
    const uint32_t a = mesh_.Corner(f, Ccw(iv));
    const uint32_t b = mesh_.Corner(f, Cw(iv));
    const Side oa = SideOf(a);
    const Side ob = SideOf(b);
    out_->end_face = f;
    if (oa == Side::kRight && ob == Side::kLeft) {
      *status = Enter(f);
      if (!status->ok()) return true;
      const ProfileRegion region = FaceRegion(f);
      if (ContainsQ(f)) {
        Finish(region);
        return true;
      }
      StopOnEdge(region, a, b);
      *status = CrossEdge(iv);
      return true;
    }
    // Along edge (v, a) (opposite b) or (v, b) (opposite a).
    for (const auto& [w, edge] :
         {std::pair{a, Cw(iv)}, std::pair{b, Ccw(iv)}}) {
      if (SideOf(w) != Side::kOn || !Ahead(PointOf(v), w)) continue;
      const ProfileRegion region = EdgeRegion(f, edge);
      if (ContainsQ(f)) {
        Finish(region);
      } else {
        StopAtVertex(region, f, w);
      }
      return true;
    }
    return false;
  }

  // At vertex_ (a corner of face_): into the face or along the edge the
  // line leaves it by, trying face_ first and then the faces around it.
  Status StepAtVertex() {
    Status status;
    const uint32_t start = face_;
    if (StepFromVertexInto(start, &status) ||
        mesh_.AnyFaceAround(start, vertex_, [&](uint32_t g) {
          return StepFromVertexInto(g, &status);
        })) {
      return status;
    }
    LeaveHull();
    return Status::OK();
  }

  const ServingMesh& mesh_;
  const Point2 p_;
  const Point2 q_;
  // CompareXY(p, q): which way "ahead" is, lexicographically.
  const int direction_;
  const uint64_t max_faces_;
  uint64_t* const faces_;
  SegmentTrace* const out_;
  State state_ = State::kDone;
  // The face the walk is in; at a vertex, a face with vertex_ as a corner.
  uint32_t face_ = 0;
  uint32_t vertex_ = 0;
};

}  // namespace

Status WalkSegment(const ServingMesh& mesh, const MeshWalkOutcome& at,
                   const Point2& p, const Point2& q, uint64_t max_faces,
                   uint64_t* faces, SegmentTrace* out) {
  return SegmentWalker(mesh, p, q, max_faces, faces, out).Run(at);
}

Status TooManyFaces(uint64_t max_faces) {
  return Status::ResourceExhausted(
      StrCat({"profile: the line crosses more than ", std::to_string(max_faces),
              " triangle edges, the limit per request"}));
}

}  // namespace locator
