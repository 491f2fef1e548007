#include "server/core/walk.h"

namespace locator {

namespace {

// CGAL's faces as a VisibilityWalk topology.
class CgalTopology {
 public:
  using Face = Triangulation::Face_handle;

  explicit CgalTopology(const Triangulation& t) : t_(t) {}

  Side SideOf(Face f, int i, const Point2& q) const {
    return Orientation(Triangulation::FromCgal(f->vertex(Ccw(i))->point()),
                       Triangulation::FromCgal(f->vertex(Cw(i))->point()), q);
  }
  bool Next(Face f, int i, Face* next) const {
    *next = f->neighbor(i);
    return !t_.IsInfinite(*next);
  }
  int EntryIndex(Face next, Face from) const { return next->index(from); }

 private:
  const Triangulation& t_;
};

}  // namespace

WalkOutcome Walk(const Triangulation& t, Triangulation::Face_handle start,
                 const Point2& q) {
  return VisibilityWalk(CgalTopology(t), start, q);
}

}  // namespace locator
