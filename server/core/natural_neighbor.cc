#include "server/core/natural_neighbor.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "server/core/walk.h"

namespace locator {

namespace {

using Face_handle = Triangulation::Face_handle;
using Vertex_handle = Triangulation::Vertex_handle;
using CgalPoint = Triangulation::CgalPoint;

// An edge of the conflict zone's boundary as CGAL represents it: the face
// outside the zone (possibly infinite) and the index, in that face, of the
// corner opposite the edge. Seen from inside the zone the edge runs from
// face->vertex(Cw(index)) to face->vertex(Ccw(index)), counter-clockwise.
struct BoundaryEdge {
  Face_handle face;
  int index;
};

// Whether q is strictly inside the circumcircle of the finite face f.
bool InConflict(Face_handle f, const CgalPoint& q) {
  return CGAL::side_of_oriented_circle(
             f->vertex(0)->point(), f->vertex(1)->point(),
             f->vertex(2)->point(), q) == CGAL::ON_POSITIVE_SIDE;
}

// The boundary of the Bowyer-Watson conflict zone of q (the faces whose
// circumcircle contains q strictly), counter-clockwise, as CGAL's
// get_boundary_of_conflicts lists it: a depth-first search from `start`,
// which is in conflict, leaving every face through the edge after the one
// it was entered by. q is strictly inside the convex hull, so no infinite
// face is in conflict. The zone is a triangulated disk without interior
// vertices (an interior vertex's whole Voronoi cell would go to q), so its
// faces and the edges between them form a tree: the search enters every
// face once, through its edge towards `start`, and needs no record of the
// faces it has seen. Nothing is marked, so concurrent calls do not race.
void ConflictBoundary(const Triangulation& t, Face_handle start,
                      const CgalPoint& q, std::vector<BoundaryEdge>* boundary) {
  // Each entry is a face in conflict and the edge to cross next; the top
  // is crossed first.
  std::vector<std::pair<Face_handle, int>> stack = {
      {start, 2}, {start, 1}, {start, 0}};
  while (!stack.empty()) {
    const auto [face, i] = stack.back();
    stack.pop_back();
    const Face_handle next = face->neighbor(i);
    const int j = next->index(face);
    // A constrained edge stops the search as in CGAL's constrained
    // Delaunay triangulation: callers serve no constraints, and this keeps
    // the search finite even if one did.
    if (t.IsInfinite(next) || face->is_constrained(i) || !InConflict(next, q)) {
      boundary->push_back({next, j});
    } else {
      stack.emplace_back(next, Cw(j));
      stack.emplace_back(next, Ccw(j));
    }
  }
}

// Maps dataset points into a frame centred on q and scaled by a power of
// two (exactly) so that the conflict zone spans about 1 (every corner of
// its faces is a boundary vertex): the weights do not change, and the
// circumcentres and areas below keep their precision at any scale of the
// dataset, where in dataset units they would overflow beyond ~1e154 and
// underflow below ~1e-154.
class LocalFrame {
 public:
  LocalFrame(const Point2& q, const std::vector<BoundaryEdge>& boundary)
      : q_(q) {
    double extent = 0;
    for (const BoundaryEdge& e : boundary) {
      const CgalPoint& p = e.face->vertex(Cw(e.index))->point();
      extent = std::max({extent, std::abs(p.x() - q.x), std::abs(p.y() - q.y)});
    }
    exponent_ = -std::ilogb(extent);
  }

  CgalPoint operator()(Vertex_handle v) const {
    const CgalPoint& p = v->point();
    return CgalPoint(std::ldexp(p.x() - q_.x, exponent_),
                     std::ldexp(p.y() - q_.y, exponent_));
  }

  // The circumcentre of f's corners, in the frame.
  CgalPoint Center(Face_handle f) const {
    return CGAL::circumcenter((*this)(f->vertex(0)), (*this)(f->vertex(1)),
                              (*this)(f->vertex(2)));
  }

 private:
  Point2 q_;
  int exponent_ = 0;
};

// Twice the signed area of the polygon, positive when counter-clockwise.
double TwiceArea(const std::vector<CgalPoint>& polygon) {
  double area = 0;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const CgalPoint& a = polygon[k];
    const CgalPoint& b = polygon[(k + 1) % polygon.size()];
    area += a.x() * b.y() - a.y() * b.x();
  }
  return area;
}

// Sibson's coordinates of q from the boundary of its conflict zone, as
// CGAL's natural_neighbors_2: boundary vertex `current` loses to q the part
// of its Voronoi cell bounded by the circumcentres of (current, next, q),
// of the zone's faces around `current` (counter-clockwise from the edge to
// `next` to the edge from `prev`), and of (prev, current, q). Vertices
// that lose no area are left out.
void StolenAreas(const Point2& q, const std::vector<BoundaryEdge>& boundary,
                 std::vector<NaturalNeighbor>* out) {
  const LocalFrame local(q, boundary);
  const CgalPoint origin(0, 0);  // q
  std::vector<CgalPoint> polygon;
  double sum = 0;
  Vertex_handle prev = boundary.back().face->vertex(Cw(boundary.back().index));
  for (const BoundaryEdge& e : boundary) {
    const Vertex_handle current = e.face->vertex(Cw(e.index));
    const Vertex_handle next = e.face->vertex(Ccw(e.index));
    polygon.clear();
    polygon.push_back(CGAL::circumcenter(local(current), local(next), origin));
    Face_handle f = e.face->neighbor(e.index);
    polygon.push_back(local.Center(f));
    while (!f->has_vertex(prev)) {
      f = f->neighbor(Ccw(f->index(current)));
      polygon.push_back(local.Center(f));
    }
    polygon.push_back(CGAL::circumcenter(local(prev), local(current), origin));
    const double area = TwiceArea(polygon);
    if (area > 0) {
      out->push_back({current, area});
      sum += area;
    }
    prev = current;
  }
  for (NaturalNeighbor& n : *out) n.weight /= sum;
}

// q on the hull edge i of f (not at a corner): its endpoints, weighted by
// where q divides the edge, measured along the edge's longer axis so that
// both weights are positive.
void HullEdgeWeights(Face_handle f, int i, const Point2& q,
                     std::vector<NaturalNeighbor>* out) {
  const Vertex_handle a = f->vertex(Ccw(i));
  const Vertex_handle b = f->vertex(Cw(i));
  const Point2 pa = Triangulation::FromCgal(a->point());
  const Point2 pb = Triangulation::FromCgal(b->point());
  const bool along_x = std::abs(pa.x - pb.x) >= std::abs(pa.y - pb.y);
  const double to_a = along_x ? std::abs(pa.x - q.x) : std::abs(pa.y - q.y);
  const double to_b = along_x ? std::abs(pb.x - q.x) : std::abs(pb.y - q.y);
  out->push_back({a, to_b / (to_a + to_b)});
  out->push_back({b, to_a / (to_a + to_b)});
}

}  // namespace

bool SibsonCoordinates(const Triangulation& t, Face_handle f, const Point2& q,
                       std::vector<NaturalNeighbor>* out) {
  out->clear();
  // From a face whose closed triangle holds q the walk stays there and
  // tells face, edge and vertex apart with exact orientation tests.
  const WalkOutcome where = Walk(t, f, q);
  switch (where.type) {
    case LocationType::kOutsideConvexHull:
      return false;
    case LocationType::kVertex:
      out->push_back({where.face->vertex(where.feature), 1});
      return true;
    case LocationType::kEdge:
      if (t.IsInfinite(where.face->neighbor(where.feature))) {
        HullEdgeWeights(where.face, where.feature, q, out);
        return true;
      }
      break;
    default:
      break;
  }
  std::vector<BoundaryEdge> boundary;
  ConflictBoundary(t, where.face, Triangulation::ToCgal(q), &boundary);
  StolenAreas(q, boundary, out);
  return true;
}

}  // namespace locator
