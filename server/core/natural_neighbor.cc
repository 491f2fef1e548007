#include "server/core/natural_neighbor.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "server/core/circle.h"
#include "server/core/mesh_walk.h"

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

// Maps dataset points into a frame centred on q and scaled by a power of
// two (exactly) so that the conflict zone spans about 1 (every corner of
// its faces is a boundary vertex): the weights do not change, and the
// circumcentres and areas below keep their precision at any scale of the
// dataset, where in dataset units they would overflow beyond ~1e154 and
// underflow below ~1e-154.
class LocalFrame {
 public:
  LocalFrame(const ServingMesh& mesh, const Point2& q,
             const std::vector<BoundaryEdge>& boundary)
      : mesh_(mesh), q_(q) {
    double extent = 0;
    for (const BoundaryEdge& e : boundary) {
      const Point2& p = mesh.CornerPoint(e.face, Ccw(e.index));
      extent = std::max({extent, std::abs(p.x - q.x), std::abs(p.y - q.y)});
    }
    exponent_ = -std::ilogb(extent);
  }

  // Mesh vertex v, in the frame.
  Point2 operator()(uint32_t v) const {
    const Point2& p = mesh_.arrays().points[v];
    return Point2{std::ldexp(p.x - q_.x, exponent_),
                  std::ldexp(p.y - q_.y, exponent_)};
  }

  // The circumcentre of f's corners, in the frame.
  Point2 Center(uint32_t f) const {
    return Circumcenter((*this)(mesh_.Corner(f, 0)),
                        (*this)(mesh_.Corner(f, 1)),
                        (*this)(mesh_.Corner(f, 2)));
  }

 private:
  const ServingMesh& mesh_;
  Point2 q_;
  int exponent_ = 0;
};

// Twice the signed area of the polygon, positive when counter-clockwise.
double TwiceArea(const std::vector<Point2>& polygon) {
  double area = 0;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Point2& a = polygon[k];
    const Point2& b = polygon[(k + 1) % polygon.size()];
    area += a.x * b.y - a.y * b.x;
  }
  return area;
}

// Sibson's coordinates of q from the boundary of its conflict zone, as
// CGAL's natural_neighbors_2: boundary vertex `current` loses to q the part
// of its Voronoi cell bounded by the circumcentres of (current, next, q),
// of the zone's faces around `current` (counter-clockwise from the edge to
// `next` to the edge from `prev`), and of (prev, current, q). Vertices
// that lose no area are left out.
void StolenAreas(const ServingMesh& mesh, const Point2& q,
                 const std::vector<BoundaryEdge>& boundary,
                 std::vector<NaturalNeighbor>* out) {
  const LocalFrame local(mesh, q, boundary);
  const Point2 origin{0, 0};  // q
  std::vector<Point2> polygon;
  double sum = 0;
  uint32_t prev = mesh.Corner(boundary.back().face, Ccw(boundary.back().index));
  for (const BoundaryEdge& e : boundary) {
    const uint32_t current = mesh.Corner(e.face, Ccw(e.index));
    const uint32_t next = mesh.Corner(e.face, Cw(e.index));
    polygon.clear();
    polygon.push_back(Circumcenter(local(current), local(next), origin));
    uint32_t f = e.face;
    polygon.push_back(local.Center(f));
    while (mesh.IndexOf(f, prev) < 0) {
      f = mesh.Neighbor(f, Ccw(mesh.IndexOf(f, current)));
      polygon.push_back(local.Center(f));
    }
    polygon.push_back(Circumcenter(local(prev), local(current), origin));
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
void HullEdgeWeights(const ServingMesh& mesh, uint32_t f, int i,
                     const Point2& q, std::vector<NaturalNeighbor>* out) {
  const uint32_t a = mesh.Corner(f, Ccw(i));
  const uint32_t b = mesh.Corner(f, Cw(i));
  const Point2& pa = mesh.arrays().points[a];
  const Point2& pb = mesh.arrays().points[b];
  const bool along_x = std::abs(pa.x - pb.x) >= std::abs(pa.y - pb.y);
  const double to_a = along_x ? std::abs(pa.x - q.x) : std::abs(pa.y - q.y);
  const double to_b = along_x ? std::abs(pb.x - q.x) : std::abs(pb.y - q.y);
  out->push_back({a, to_b / (to_a + to_b)});
  out->push_back({b, to_a / (to_a + to_b)});
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
  StolenAreas(mesh, q, boundary, out);
  return true;
}

}  // namespace locator
