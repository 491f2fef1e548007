#include "server/core/geometry/natural_neighbor.h"

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "server/core/cgal/orientation.h"
#include "server/core/geometry/circle.h"
#include "server/core/geometry/wide_math.h"
#include "server/core/mesh/mesh_walk.h"

namespace locator {

namespace {

// An edge of the conflict zone's boundary, seen from inside the zone: edge
// `index` of the zone's face `face`, running counter-clockwise from corner
// Ccw(index) to corner Cw(index).
struct BoundaryEdge {
  uint32_t face;
  int index;
};

// Whether q is strictly inside the circumcircle of face f.
bool InConflict(const ServingMesh& mesh, uint32_t f, const Point2& q) {
  return InsideCircumcircle(mesh.CornerPoint(f, 0), mesh.CornerPoint(f, 1),
                            mesh.CornerPoint(f, 2), q);
}

// The boundary of the Bowyer-Watson conflict zone of q (the faces whose
// circumcircle contains q strictly), counter-clockwise, as CGAL's
// get_boundary_of_conflicts lists it: a depth-first search from `start`,
// which is in conflict, leaving every face through the edge after the one
// it was entered by. q is strictly inside the convex hull, so the zone does
// not reach beyond the hull. The zone is a triangulated disk without
// interior vertices (an interior vertex's whole Voronoi cell would go to q),
// so its faces and the edges between them form a tree: the search enters
// every face once, through its edge towards `start`, and needs no record of
// the faces it has seen. Nothing is marked, so concurrent calls do not race.
void ConflictBoundary(const ServingMesh& mesh, uint32_t start, const Point2& q,
                      std::vector<BoundaryEdge>* boundary) {
  // Each entry is a face in conflict and the edge to cross next; the top
  // is crossed first.
  std::vector<std::pair<uint32_t, int>> stack = {
      {start, 2}, {start, 1}, {start, 0}};
  while (!stack.empty()) {
    const auto [face, i] = stack.back();
    stack.pop_back();
    const uint32_t next = mesh.Neighbor(face, i);
    // A constrained edge stops the search as in CGAL's constrained
    // Delaunay triangulation: callers serve no constraints, and this keeps
    // the search finite even if one did.
    if (ServingMesh::IsHull(next) || mesh.IsConstrained(face, i) ||
        !InConflict(mesh, next, q)) {
      boundary->push_back({face, i});
    } else {
      const int j = mesh.MirrorIndex(next, face);
      stack.emplace_back(next, Cw(j));
      stack.emplace_back(next, Ccw(j));
    }
  }
}

// A point of a frame centred on q, in the number type Real.
template <class Real>
struct FramePoint {
  Real x = 0;
  Real y = 0;
};

// The centre of the circle through a, b and c, computed from a.
template <class Real>
FramePoint<Real> CircumcenterFrom(const FramePoint<Real>& a,
                                  const FramePoint<Real>& b,
                                  const FramePoint<Real>& c) {
  const Real bx = b.x - a.x;
  const Real by = b.y - a.y;
  const Real cx = c.x - a.x;
  const Real cy = c.y - a.y;
  const Real b2 = bx * bx + by * by;
  const Real c2 = cx * cx + cy * cy;
  const Real d = 2 * (bx * cy - by * cx);
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

// The centre of the circle through a, b and c; in floating point computed
// from the corner opposite the longest side, whose angle is the largest, so
// that the cross product there cancels least (from a needle's far tip it
// would lose as many digits as the needle is thin). Not finite when they
// are collinear to within the rounding.
template <class Real>
FramePoint<Real> Circumcenter(const FramePoint<Real>& a,
                              const FramePoint<Real>& b,
                              const FramePoint<Real>& c) {
  if constexpr (std::is_floating_point_v<Real>) {
    const auto length2 = [](const FramePoint<Real>& u,
                            const FramePoint<Real>& v) {
      return (u.x - v.x) * (u.x - v.x) + (u.y - v.y) * (u.y - v.y);
    };
    const Real bc = length2(b, c);
    const Real ca = length2(c, a);
    const Real ab = length2(a, b);
    if (ca > bc && ca >= ab) return CircumcenterFrom(b, c, a);
    if (ab > bc && ab > ca) return CircumcenterFrom(c, a, b);
  }
  return CircumcenterFrom(a, b, c);
}

// Dataset points in Wide, in a frame centred on q and scaled by a power of
// two so that the conflict zone spans about 1 (every corner of its faces is
// a boundary vertex): the weights do not change, and neither the
// differences from q (up to 2 DBL_MAX) nor the squares and products of the
// circumcentres and areas overflow or underflow at any scale of the
// dataset, where in dataset units and doubles they would beyond ~1e154 and
// below ~1e-154.
class WideFrame {
 public:
  using Real = Wide;

  WideFrame(const ServingMesh& mesh, const Point2& q,
            const std::vector<BoundaryEdge>& boundary)
      : mesh_(mesh), q_(q) {
    Wide extent = 0;
    for (const BoundaryEdge& e : boundary) {
      const Point2& p = mesh.CornerPoint(e.face, Ccw(e.index));
      extent = std::max(
          {extent, std::abs(Wide{p.x} - q.x), std::abs(Wide{p.y} - q.y)});
    }
    scale_ = std::ldexp(Wide{1}, -std::ilogb(extent));
  }

  // Mesh vertex v, in the frame (a power of two scales exactly).
  FramePoint<Wide> operator()(uint32_t v) const {
    const Point2& p = mesh_.arrays().points[v];
    return {(Wide{p.x} - q_.x) * scale_, (Wide{p.y} - q_.y) * scale_};
  }

 private:
  const ServingMesh& mesh_;
  Point2 q_;
  Wide scale_ = 1;
};

// Dataset points as exact rationals, in a frame centred on q.
class ExactFrame {
 public:
  using Real = CGAL::Exact_rational;

  ExactFrame(const ServingMesh& mesh, const Point2& q) : mesh_(mesh), q_(q) {}

  FramePoint<Real> operator()(uint32_t v) const {
    const Point2& p = mesh_.arrays().points[v];
    return {Real(p.x) - q_.x, Real(p.y) - q_.y};
  }

 private:
  const ServingMesh& mesh_;
  Point2 q_;
};

// Twice the signed area of the polygon, positive when counter-clockwise.
template <class Real>
Real TwiceArea(const std::vector<FramePoint<Real>>& polygon) {
  Real area = 0;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const FramePoint<Real>& a = polygon[k];
    const FramePoint<Real>& b = polygon[(k + 1) % polygon.size()];
    area += a.x * b.y - a.y * b.x;
  }
  return area;
}

// Twice the area each vertex of the boundary of q's conflict zone loses to
// q, as CGAL's natural_neighbors_2 computes it: boundary vertex `current`
// loses the part of its Voronoi cell bounded by the circumcentres of
// (current, next, q), of the zone's faces around `current`
// (counter-clockwise from the edge to `next` to the edge from `prev`), and
// of (prev, current, q). Parallel lists, in boundary order. False if q is
// on the line of a boundary edge (exactly: Orientation), where a circle
// through the edge and q does not exist; q strictly inside the hull and
// off every edge of its zone's boundary never is.
template <class Frame>
bool StolenAreas(const ServingMesh& mesh, const Point2& q, const Frame& frame,
                 const std::vector<BoundaryEdge>& boundary,
                 std::vector<uint32_t>* vertices,
                 std::vector<typename Frame::Real>* areas) {
  for (const BoundaryEdge& e : boundary) {
    if (Orientation(mesh.CornerPoint(e.face, Ccw(e.index)),
                    mesh.CornerPoint(e.face, Cw(e.index)), q) == Side::kOn) {
      return false;
    }
  }
  using Point = FramePoint<typename Frame::Real>;
  const auto center = [&](uint32_t f) {
    return Circumcenter(frame(mesh.Corner(f, 0)), frame(mesh.Corner(f, 1)),
                        frame(mesh.Corner(f, 2)));
  };
  const Point origin;  // q
  std::vector<Point> polygon;
  uint32_t prev = mesh.Corner(boundary.back().face, Ccw(boundary.back().index));
  for (const BoundaryEdge& e : boundary) {
    const uint32_t current = mesh.Corner(e.face, Ccw(e.index));
    const uint32_t next = mesh.Corner(e.face, Cw(e.index));
    polygon.clear();
    polygon.push_back(Circumcenter(frame(current), frame(next), origin));
    uint32_t f = e.face;
    polygon.push_back(center(f));
    while (mesh.IndexOf(f, prev) < 0) {
      f = mesh.Neighbor(f, Ccw(mesh.IndexOf(f, current)));
      polygon.push_back(center(f));
    }
    polygon.push_back(Circumcenter(frame(prev), frame(current), origin));
    vertices->push_back(current);
    areas->push_back(TwiceArea(polygon));
    prev = current;
  }
  return true;
}

// Whether the areas make trustworthy weights: finite, a positive sum, and
// Sibson's linear precision (the weighted vertices are q: sum of area_i
// (p_i - q) is 0) to a relative 1e-11. Rounding in a needle's far
// circumcentre breaks it long before the weights are off by that much.
bool TrustedAreas(const ServingMesh& mesh, const Point2& q,
                  const std::vector<uint32_t>& vertices,
                  const std::vector<Wide>& areas) {
  Wide sum = 0, sx = 0, sy = 0, mx = 0, my = 0;
  for (size_t k = 0; k < vertices.size(); ++k) {
    if (!std::isfinite(areas[k])) return false;
    if (!(areas[k] > 0)) continue;
    const Point2& p = mesh.arrays().points[vertices[k]];
    const Wide dx = Wide{p.x} - q.x;
    const Wide dy = Wide{p.y} - q.y;
    sum += areas[k];
    sx += areas[k] * dx;
    sy += areas[k] * dy;
    mx += areas[k] * std::abs(dx);
    my += areas[k] * std::abs(dy);
  }
  constexpr Wide kTolerance = 1e-11;
  return sum > 0 && std::abs(sx) <= kTolerance * mx &&
         std::abs(sy) <= kTolerance * my;
}

// Sibson's coordinates of q from the boundary of its conflict zone into
// `out`, leaving out vertices that lose no area: computed in Wide, and
// again in exact rationals where TrustedAreas() doubts the Wide areas
// (rare: needles near q). False, with `out` empty, where StolenAreas()
// is, or the exact areas sum to 0.
bool SibsonFromBoundary(const ServingMesh& mesh, const Point2& q,
                        const std::vector<BoundaryEdge>& boundary,
                        std::vector<NaturalNeighbor>* out) {
  std::vector<uint32_t> vertices;
  std::vector<Wide> areas;
  if (!StolenAreas(mesh, q, WideFrame(mesh, q, boundary), boundary, &vertices,
                   &areas)) {
    return false;
  }
  if (TrustedAreas(mesh, q, vertices, areas)) {
    Wide sum = 0;
    for (const Wide area : areas) sum += area > 0 ? area : 0;
    for (size_t k = 0; k < vertices.size(); ++k) {
      if (areas[k] > 0) {
        out->push_back({vertices[k], static_cast<double>(areas[k] / sum)});
      }
    }
    return true;
  }
  using Exact = ExactFrame::Real;
  std::vector<Exact> exact;
  vertices.clear();
  if (!StolenAreas(mesh, q, ExactFrame(mesh, q), boundary, &vertices, &exact)) {
    return false;
  }
  Exact sum = 0;
  for (const Exact& area : exact) {
    if (area > 0) sum += area;
  }
  if (!(sum > 0)) return false;
  for (size_t k = 0; k < vertices.size(); ++k) {
    if (exact[k] > 0) {
      out->push_back({vertices[k], CGAL::to_double(Exact(exact[k] / sum))});
    }
  }
  return true;
}

// q on the hull edge i of f (not at a corner): its endpoints, weighted by
// where q divides the edge, measured along the edge's longer axis so that
// both weights are positive (in Wide: the edge may be longer than a
// double).
void HullEdgeWeights(const ServingMesh& mesh, uint32_t f, int i,
                     const Point2& q, std::vector<NaturalNeighbor>* out) {
  const uint32_t a = mesh.Corner(f, Ccw(i));
  const uint32_t b = mesh.Corner(f, Cw(i));
  const Point2& pa = mesh.arrays().points[a];
  const Point2& pb = mesh.arrays().points[b];
  const bool along_x =
      std::abs(Wide{pa.x} - pb.x) >= std::abs(Wide{pa.y} - pb.y);
  const Wide to_a =
      along_x ? std::abs(Wide{pa.x} - q.x) : std::abs(Wide{pa.y} - q.y);
  const Wide to_b =
      along_x ? std::abs(Wide{pb.x} - q.x) : std::abs(Wide{pb.y} - q.y);
  out->push_back({a, static_cast<double>(to_b / (to_a + to_b))});
  out->push_back({b, static_cast<double>(to_a / (to_a + to_b))});
}

}  // namespace

bool SibsonCoordinates(const ServingMesh& mesh, uint32_t f, const Point2& q,
                       std::vector<NaturalNeighbor>* out) {
  out->clear();
  // From a face whose closed triangle holds q the walk stays there and
  // tells face, edge and vertex apart with exact orientation tests.
  const MeshWalkOutcome where = Walk(mesh, f, q);
  switch (where.type) {
    case LocationType::kOutsideConvexHull:
      return false;
    case LocationType::kVertex:
      out->push_back({mesh.Corner(where.face, where.feature), 1});
      return true;
    case LocationType::kEdge:
      if (ServingMesh::IsHull(mesh.Neighbor(where.face, where.feature))) {
        HullEdgeWeights(mesh, where.face, where.feature, q, out);
        return true;
      }
      break;
    default:
      break;
  }
  std::vector<BoundaryEdge> boundary;
  ConflictBoundary(mesh, where.face, q, &boundary);
  return SibsonFromBoundary(mesh, q, boundary, out);
}

}  // namespace locator
