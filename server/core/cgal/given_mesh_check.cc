// GivenMeshBuilder's checks (see given_mesh.h): the points, the triangles,
// their edges, and the faces of the boundary's triangulation inside and
// outside the mesh.

#include <CGAL/intersections.h>

#include <algorithm>
#include <charconv>
#include <numeric>
#include <string>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include "server/core/cgal/given_mesh_builder.h"

namespace locator {

namespace {

std::string PointText(double x, double y) {
  const auto shortest = [](double v) {
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof(text), v);
    return std::string(text, error == std::errc() ? end : text);
  };
  return "(" + shortest(x) + ", " + shortest(y) + ")";
}

}  // namespace

std::string GivenMeshBuilder::TriangleName(size_t k) const {
  const std::array<uint32_t, 3>& t = d_.constraints.triangles[k];
  return "mesh triangle " + std::to_string(k) + " (" + std::to_string(t[0]) +
         " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + ")";
}

Status GivenMeshBuilder::Overlaps(size_t k) const {
  return Status::InvalidArgument(
      TriangleName(k) +
      " is not a face of the triangulation of the mesh's edges: it overlaps "
      "another triangle or contains a point");
}

Status GivenMeshBuilder::Check() {
  Status s = MergePoints();
  if (s.ok()) s = CheckTriangles();
  if (s.ok()) s = PairEdges();
  if (s.ok()) s = TriangulateBoundary();
  if (s.ok()) s = SideFaces();
  if (s.ok()) s = CheckUnusedPoints();
  return s;
}

Status GivenMeshBuilder::MergePoints() {
  const std::vector<Point2>& pts = d_.points;
  const size_t n = pts.size();
  for (size_t i = 0; i < n; ++i) {
    if (!IsFinite(pts[i])) {
      return Status::InvalidArgument("point " + std::to_string(i) +
                                     " has a non-finite coordinate");
    }
  }
  if (!d_.values.empty() && d_.values.size() != n) {
    return Status::InvalidArgument("dataset values and points differ in size");
  }
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&pts](uint32_t a, uint32_t b) {
    return std::tie(pts[a].x, pts[a].y, a) < std::tie(pts[b].x, pts[b].y, b);
  });
  first_.resize(n);
  std::vector<std::pair<Kernel::Point_2, VertexInfo>> distinct;
  for (size_t k = 0; k < n; ++k) {
    const uint32_t i = order[k];
    if (k > 0 && pts[order[k - 1]].x == pts[i].x &&
        pts[order[k - 1]].y == pts[i].y) {
      first_[i] = first_[order[k - 1]];
      continue;
    }
    first_[i] = i;
    distinct.emplace_back(Kernel::Point_2(pts[i].x, pts[i].y), VertexInfo{i});
  }
  distinct_ = distinct.size();
  if (distinct_ < 3) {
    return Status::InvalidArgument(
        "dataset has " + std::to_string(distinct_) +
        " distinct point(s); a triangulation needs at least 3 that are not "
        "all collinear");
  }
  const Kernel::Point_2& a = distinct[0].first;
  const Kernel::Point_2& b = distinct[1].first;
  if (std::all_of(distinct.begin() + 2, distinct.end(), [&](const auto& p) {
        return CGAL::orientation(a, b, p.first) == CGAL::COLLINEAR;
      })) {
    return Status::InvalidArgument(
        "all " + std::to_string(distinct_) +
        " distinct points are collinear; no triangle can be formed");
  }
  cdt_.insert(distinct.begin(), distinct.end());
  vertex_.assign(n, Cdt::Vertex_handle());
  for (auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end();
       ++v) {
    vertex_[v->info().id] = v;
  }
  return Status::OK();
}

Status GivenMeshBuilder::CheckTriangles() {
  const size_t n = d_.points.size();
  tri_.resize(d_.constraints.triangles.size());
  for (size_t k = 0; k < tri_.size(); ++k) {
    const std::array<uint32_t, 3>& given = d_.constraints.triangles[k];
    for (int i = 0; i < 3; ++i) {
      if (given[i] >= n) {
        return Status::InvalidArgument(
            TriangleName(k) + ": corner index " + std::to_string(given[i]) +
            " is out of range (" + std::to_string(n) + " points)");
      }
      tri_[k][i] = first_[given[i]];
    }
    std::array<uint32_t, 3>& t = tri_[k];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      return Status::InvalidArgument(TriangleName(k) + " has repeated corners");
    }
    const auto orientation = CGAL::orientation(
        vertex_[t[0]]->point(), vertex_[t[1]]->point(), vertex_[t[2]]->point());
    if (orientation == CGAL::COLLINEAR) {
      return Status::InvalidArgument(TriangleName(k) +
                                     " has collinear corners");
    }
    if (orientation == CGAL::CLOCKWISE) std::swap(t[1], t[2]);
  }
  return Status::OK();
}

Status GivenMeshBuilder::PairEdges() {
  // Every half-edge keyed by its ids, low first; the uses of one edge are
  // then a run.
  std::vector<std::tuple<uint32_t, uint32_t, uint32_t>> uses;
  uses.reserve(3 * tri_.size());
  for (uint32_t h = 0; h < 3 * tri_.size(); ++h) {
    const auto [lo, hi] = std::minmax({From(h), To(h)});
    uses.emplace_back(lo, hi, h);
  }
  std::sort(uses.begin(), uses.end());
  twin_.assign(3 * tri_.size(), kNone);
  for (size_t first = 0, next; first < uses.size(); first = next) {
    const auto [lo, hi, h] = uses[first];
    next = first + 1;
    while (next < uses.size() && std::get<0>(uses[next]) == lo &&
           std::get<1>(uses[next]) == hi) {
      ++next;
    }
    ++mesh_edges_;
    if (next - first >= 3) {
      return Status::InvalidArgument(
          "mesh edge (" + std::to_string(lo) + " " + std::to_string(hi) +
          ") is shared by triangles " + std::to_string(h / 3) + ", " +
          std::to_string(std::get<2>(uses[first + 1]) / 3) + " and " +
          std::to_string(std::get<2>(uses[first + 2]) / 3) +
          " (not a manifold)");
    }
    if (next - first == 1) {
      boundary_.emplace(Key(From(h), To(h)), h);
      continue;
    }
    // Two triangles on one side of the edge overlap; on both, they meet.
    const uint32_t g = std::get<2>(uses[first + 1]);
    if (From(g) == From(h)) {
      std::array<uint32_t, 3> a = tri_[h / 3], b = tri_[g / 3];
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      if (a == b) {
        return Status::InvalidArgument(TriangleName(g / 3) +
                                       " repeats an earlier triangle");
      }
      return Overlaps(g / 3);
    }
    twin_[h] = g;
    twin_[g] = h;
  }
  return Status::OK();
}

std::string GivenMeshBuilder::EdgeName(uint32_t h) const {
  const auto [lo, hi] = std::minmax({From(h), To(h)});
  return "mesh edge (" + std::to_string(lo) + " " + std::to_string(hi) +
         ") of triangle " + std::to_string(h / 3);
}

Status GivenMeshBuilder::TriangulateBoundary() {
  // In the order of their ids, as Triangulation::Build inserts mesh edges,
  // so that a crossing is named as it names it.
  std::vector<std::pair<std::pair<uint32_t, uint32_t>, uint32_t>> edges;
  for (uint32_t h = 0; h < twin_.size(); ++h) {
    if (twin_[h] == kNone) edges.push_back({std::minmax({From(h), To(h)}), h});
  }
  std::sort(edges.begin(), edges.end());
  for (size_t k = 0; k < edges.size(); ++k) {
    const uint32_t h = edges[k].second;
    cdt_.insert_constraint(vertex_[From(h)], vertex_[To(h)]);
    if (cdt_.number_of_vertices() == distinct_) continue;
    // CGAL added a vertex where h crosses an edge inserted before it.
    const auto point = [&](uint32_t id) { return vertex_[id]->point(); };
    const auto crosses = [&](uint32_t g) {
      const auto side = [&](uint32_t a, uint32_t b, uint32_t c) {
        return static_cast<int>(
            CGAL::orientation(point(a), point(b), point(c)));
      };
      return side(From(g), To(g), From(h)) * side(From(g), To(g), To(h)) < 0 &&
             side(From(h), To(h), From(g)) * side(From(h), To(h), To(g)) < 0;
    };
    for (size_t j = 0; j < k; ++j) {
      const uint32_t g = edges[j].second;
      if (!crosses(g)) continue;
      // Where the two cross, constructed as CGAL constructs the vertex.
      const auto at =
          CGAL::intersection(Kernel::Segment_2(point(From(g)), point(To(g))),
                             Kernel::Segment_2(point(From(h)), point(To(h))));
      const auto* p = at ? boost::get<Kernel::Point_2>(&*at) : nullptr;
      return Status::InvalidArgument(
          EdgeName(g) + " and " + EdgeName(h) + " cross" +
          (p != nullptr ? " at " + PointText(p->x(), p->y()) : "") +
          ": the mesh's triangles overlap");
    }
    return Status::InvalidArgument(
        EdgeName(h) + " crosses another: the mesh's triangles overlap");
  }
  return Status::OK();
}

Status GivenMeshBuilder::SideFaces() {
  // Each boundary edge's left face is inside, its right one outside, and
  // so is everything beyond the hull; both spread across unconstrained
  // edges. A face reached as both means the triangles overlap.
  std::vector<std::pair<Face_handle, uint32_t>> stack;  // face, a triangle
  const auto mark = [&](Face_handle f, Side side, uint32_t k) {
    if (f->info().side == side) return true;
    if (f->info().side != Side::kUnknown) return false;
    f->info().side = side;
    stack.emplace_back(f, k);
    return true;
  };
  for (auto f = cdt_.all_faces_begin(); f != cdt_.all_faces_end(); ++f) {
    if (cdt_.is_infinite(f)) mark(f, Side::kOutside, kNone);
  }
  // In triangle order, so that the triangle an error names does not
  // depend on the hash map's.
  for (uint32_t h = 0; h < 3 * tri_.size(); ++h) {
    if (twin_[h] != kNone) continue;
    Face_handle f;
    int i = 0;
    if (!cdt_.is_edge(vertex_[From(h)], vertex_[To(h)], f, i)) {
      return Overlaps(h / 3);  // a point lies on the edge and split it
    }
    // f lies left of the edge from its vertex ccw(i) to cw(i).
    const bool left = f->vertex(cdt_.ccw(i)) == vertex_[From(h)];
    const Face_handle inside = left ? f : f->neighbor(i);
    const Face_handle outside = left ? f->neighbor(i) : f;
    if (cdt_.is_infinite(inside) || !mark(inside, Side::kInside, h / 3) ||
        !mark(outside, Side::kOutside, h / 3)) {
      return Overlaps(h / 3);
    }
  }
  while (!stack.empty()) {
    const auto [f, k] = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      if (f->is_constrained(i)) continue;
      if (!mark(f->neighbor(i), f->info().side, k)) {
        if (k != kNone) return Overlaps(k);
        return Status::InvalidArgument(
            "the mesh's triangles overlap: a boundary does not close");
      }
    }
  }
  return Status::OK();
}

Status GivenMeshBuilder::CheckUnusedPoints() {
  std::vector<bool> used(d_.points.size());
  for (const std::array<uint32_t, 3>& t : tri_) {
    for (const uint32_t id : t) used[id] = true;
  }
  for (uint32_t id = 0; id < d_.points.size(); ++id) {
    if (first_[id] != id || used[id]) continue;
    auto f = cdt_.incident_faces(vertex_[id]);
    const auto end = f;
    do {
      if (f->info().side == Side::kInside) {
        return Status::InvalidArgument(
            "point " + std::to_string(id) + " " +
            PointText(d_.points[id].x, d_.points[id].y) +
            " lies inside the mesh but is no triangle's corner");
      }
    } while (++f != end);
  }
  return Status::OK();
}

}  // namespace locator
