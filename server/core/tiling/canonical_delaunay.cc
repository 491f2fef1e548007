#include "server/core/tiling/canonical_delaunay.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <tuple>

#include "server/core/cgal/orientation.h"

namespace locator {

bool InCanonicalCircle(const Point2& a, const Point2& b, const Point2& c,
                       const Point2& d) {
  using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  const CGAL::Oriented_side side = CGAL::side_of_oriented_circle(
      P(a.x, a.y), P(b.x, b.y), P(c.x, c.y), P(d.x, d.y));
  if (side != CGAL::ON_ORIENTED_BOUNDARY) {
    return side == CGAL::ON_POSITIVE_SIDE;
  }
  // Co-circular. The determinant's perturbation terms, largest first: the
  // term of the lexicographically largest point is its lift times the
  // orientation of the other three (with d in its place). If that point
  // is d, d rises above the plane of a, b, c: outside. Four distinct
  // co-circular points have no three collinear, so the first term decides;
  // the loop's tail only guards against a caller's collinear a, b, c.
  std::array<const Point2*, 4> points = {&a, &b, &c, &d};
  std::sort(points.begin(), points.end(), [](const Point2* p, const Point2* q) {
    return std::tie(p->x, p->y) > std::tie(q->x, q->y);
  });
  for (const Point2* p : points) {
    if (p == &d) return false;
    const Side o =
        Orientation(p == &a ? d : a, p == &b ? d : b, p == &c ? d : c);
    if (o != Side::kOn) return o == Side::kLeft;
  }
  return false;
}

size_t CountNonCanonicalEdges(const ServingMesh& mesh) {
  size_t violations = 0;
  for (uint32_t f = 0; f < mesh.num_faces(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t n = mesh.Neighbor(f, i);
      if (ServingMesh::IsHull(n) || n < f) continue;  // each edge once
      const Point2& opposite = mesh.CornerPoint(n, mesh.MirrorIndex(n, f));
      if (InCanonicalCircle(mesh.CornerPoint(f, 0), mesh.CornerPoint(f, 1),
                            mesh.CornerPoint(f, 2), opposite)) {
        ++violations;
      }
    }
  }
  // The hull is convex. Each ring edge ends where the one before it starts,
  // and runs with the triangles on its left: along the edges' own
  // direction (next, then this one) the boundary must never turn right.
  const auto hull = mesh.hull();
  const auto ends = [&](uint32_t edge, bool start) {
    const uint32_t f = ServingMesh::EdgeFace(edge);
    const int i = ServingMesh::EdgeIndex(edge);
    return mesh.CornerPoint(f, start ? Ccw(i) : Cw(i));
  };
  for (size_t k = 0; k < hull.size(); ++k) {
    const uint32_t next = hull[(k + 1) % hull.size()];
    if (Orientation(ends(next, true), ends(next, false),
                    ends(hull[k], false)) == Side::kRight) {
      ++violations;
    }
  }
  return violations;
}

}  // namespace locator
