// Triangulation::Build: the points, the constraints, the crossings and the
// domain marking, one step each (see triangulation.h for the rules).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "server/core/triangulation.h"

namespace locator {

namespace {

std::string PointText(const Point2& p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

double Distance(const Point2& a, const Point2& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace

// Builds one Triangulation. Face info is used as scratch while marking:
// -1 unvisited, else the nesting depth, then 1 (in) or 0 (out), and finally
// the triangle id or -1.
class Triangulation::Builder {
 public:
  Builder(const Dataset& dataset, Triangulation* t)
      : dataset_(dataset), t_(*t), dt_(t->dt_) {}

  Status Run() {
    Status s = InsertPoints();
    if (s.ok()) s = InsertConstraints();
    if (s.ok()) s = NameCrossings();
    if (s.ok()) s = MarkDomain();
    if (s.ok()) s = NumberTriangles();
    return s;
  }

 private:
  using Edge = Cdt::Edge;
  // A constraint segment as the input named it, for messages.
  struct InputSegment {
    Cdt::Constraint_id id;
    ConstraintKind kind;
    std::string name;
  };

  Status InsertPoints();
  Status InsertConstraints();
  Status InsertPolylines(const std::vector<Polyline>& lines, bool closed,
                         ConstraintKind kind, const std::string& what);
  Status InsertMeshEdges();
  // The vertex for p (a new one gets the next id and `value`).
  Vertex_handle VertexAt(const Point2& p, double value);
  void AddSegment(Vertex_handle a, Vertex_handle b, ConstraintKind kind,
                  std::string name);
  Status NameCrossings();
  Status MarkDomain();
  Status MarkMesh();
  void MarkRingDepth();
  Status EatSegmentRegions();
  // Sets info 0 on every face reachable from `seed` without crossing a
  // segment or ring edge.
  void Eat(Face_handle seed);
  Status NumberTriangles();
  // The number of ring segments along edge (f, i); barrier: any boundary.
  int RingCount(Face_handle f, int i) const;
  bool IsBarrier(Face_handle f, int i) const;

  bool IsBoundary(ConstraintKind kind) const {
    return kind == ConstraintKind::kRing || kind == ConstraintKind::kSegment ||
           kind == ConstraintKind::kMesh;
  }

  const Dataset& dataset_;
  Triangulation& t_;
  Cdt& dt_;
  const DatasetConstraints& c_ = dataset_.constraints;
  std::vector<InputSegment> segments_;
};

Status Triangulation::Builder::InsertPoints() {
  const std::vector<Point2>& pts = dataset_.points;
  const size_t n = pts.size();
  for (size_t i = 0; i < n; ++i) {
    if (!IsFinite(pts[i])) {
      return Status::InvalidArgument("point " + std::to_string(i) +
                                     " has a non-finite coordinate");
    }
  }
  if (!dataset_.values.empty() && dataset_.values.size() != n) {
    return Status::InvalidArgument("dataset values and points differ in size");
  }

  // Merge repeated points before CGAL sees them: CGAL's range insert would
  // keep the info of whichever copy its spatial sort visits last, and we
  // promise the first occurrence's id.
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&pts](uint32_t a, uint32_t b) {
    if (pts[a].x != pts[b].x) return pts[a].x < pts[b].x;
    if (pts[a].y != pts[b].y) return pts[a].y < pts[b].y;
    return a < b;
  });
  std::vector<uint32_t> first(n);
  std::vector<std::pair<CgalPoint, VertexInfo>> distinct;
  for (size_t k = 0; k < n; ++k) {
    const uint32_t i = order[k];
    if (k > 0 && pts[order[k - 1]].x == pts[i].x &&
        pts[order[k - 1]].y == pts[i].y) {
      first[i] = first[order[k - 1]];
      continue;
    }
    first[i] = i;
    const double value = dataset_.values.empty() ? 0.0 : dataset_.values[i];
    distinct.emplace_back(ToCgal(pts[i]), VertexInfo{int64_t{i}, value});
  }
  std::vector<uint32_t>().swap(order);

  if (distinct.size() < 3) {
    return Status::InvalidArgument(
        "dataset has " + std::to_string(distinct.size()) +
        " distinct point(s); a triangulation needs at least 3 that are not "
        "all collinear");
  }
  const CgalPoint& a = distinct[0].first;
  const CgalPoint& b = distinct[1].first;
  const bool all_collinear =
      std::all_of(distinct.begin() + 2, distinct.end(), [&](const auto& p) {
        return CGAL::orientation(a, b, p.first) == CGAL::COLLINEAR;
      });
  if (all_collinear) {
    return Status::InvalidArgument(
        "all " + std::to_string(distinct.size()) +
        " distinct points are collinear; no triangle can be formed");
  }

  t_.has_values_ = !dataset_.values.empty();
  t_.input_points_ = n;
  t_.duplicates_merged_ = n - distinct.size();
  for (const Point2& p : pts) t_.box_.Extend(p);
  // The plain CDT's range insert takes (point, info) pairs; no constraint
  // exists yet, so the hierarchy of the plus layer has nothing to track.
  dt_.Cdt::Triangulation::insert(distinct.begin(), distinct.end());
  std::vector<std::pair<CgalPoint, VertexInfo>>().swap(distinct);

  t_.by_input_.assign(n, Vertex_handle());
  for (auto v = dt_.finite_vertices_begin(); v != dt_.finite_vertices_end();
       ++v) {
    t_.by_input_[v->info().id] = v;
  }
  for (size_t i = 0; i < n; ++i) {
    if (first[i] != i) t_.by_input_[i] = t_.by_input_[first[i]];
  }
  return Status::OK();
}

Triangulation::Vertex_handle Triangulation::Builder::VertexAt(const Point2& p,
                                                              double value) {
  const Vertex_handle v = dt_.insert(ToCgal(p));
  if (v->info().id < 0) {
    v->info() = VertexInfo{static_cast<int64_t>(t_.by_input_.size()), value};
    t_.by_input_.push_back(v);
  }
  return v;
}

void Triangulation::Builder::AddSegment(Vertex_handle a, Vertex_handle b,
                                        ConstraintKind kind, std::string name) {
  if (a == b) return;  // a repeated point: no segment
  const Cdt::Constraint_id id = dt_.insert_constraint(a, b);
  t_.constraint_kinds_.emplace(id, kind);
  segments_.push_back({id, kind, std::move(name)});
}

Status Triangulation::Builder::InsertPolylines(
    const std::vector<Polyline>& lines, bool closed, ConstraintKind kind,
    const std::string& what) {
  for (size_t l = 0; l < lines.size(); ++l) {
    const Polyline& line = lines[l];
    const std::string name = what + " " + std::to_string(l);
    if (!line.values.empty() && line.values.size() != line.points.size()) {
      return Status::InvalidArgument(
          name + " has " + std::to_string(line.values.size()) + " values for " +
          std::to_string(line.points.size()) + " points");
    }
    if (line.points.size() < (closed ? 3u : 2u)) {
      return Status::InvalidArgument(
          name + " has " + std::to_string(line.points.size()) +
          " point(s); it needs at least " + (closed ? "3" : "2"));
    }
    std::vector<Vertex_handle> vertices;
    for (size_t k = 0; k < line.points.size(); ++k) {
      const Point2& p = line.points[k];
      const std::string point = name + " point " + std::to_string(k);
      if (!IsFinite(p)) {
        return Status::InvalidArgument(point + " has a non-finite coordinate");
      }
      const bool known = !line.values.empty();
      const Vertex_handle v = VertexAt(p, known ? line.values[k] : 0.0);
      if (t_.has_values_ && !known &&
          v->info().id >= static_cast<int64_t>(t_.input_points_)) {
        return Status::InvalidArgument(point + " " + PointText(p) +
                                       " is not a dataset point and has no "
                                       "value");
      }
      vertices.push_back(v);
    }
    const size_t segments = closed ? vertices.size() : vertices.size() - 1;
    for (size_t k = 0; k < segments; ++k) {
      AddSegment(vertices[k], vertices[(k + 1) % vertices.size()], kind,
                 name + " segment " + std::to_string(k));
    }
  }
  return Status::OK();
}

Status Triangulation::Builder::InsertMeshEdges() {
  const size_t n = t_.input_points_;
  // Each edge once, keyed by its merged vertex ids; the triangles using it.
  std::map<std::pair<int64_t, int64_t>, std::vector<size_t>> edges;
  for (size_t k = 0; k < c_.triangles.size(); ++k) {
    const auto& tri = c_.triangles[k];
    const std::string name =
        "mesh triangle " + std::to_string(k) + " (" + std::to_string(tri[0]) +
        " " + std::to_string(tri[1]) + " " + std::to_string(tri[2]) + ")";
    std::array<Vertex_handle, 3> v;
    for (int i = 0; i < 3; ++i) {
      if (tri[i] >= n) {
        return Status::InvalidArgument(
            name + ": corner index " + std::to_string(tri[i]) +
            " is out of range (" + std::to_string(n) + " points)");
      }
      v[i] = t_.by_input_[tri[i]];
    }
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
      return Status::InvalidArgument(name + " has repeated corners");
    }
    if (CGAL::orientation(v[0]->point(), v[1]->point(), v[2]->point()) ==
        CGAL::COLLINEAR) {
      return Status::InvalidArgument(name + " has collinear corners");
    }
    for (int i = 0; i < 3; ++i) {
      const auto key = std::minmax(v[i]->info().id, v[(i + 1) % 3]->info().id);
      std::vector<size_t>& users = edges[key];
      users.push_back(k);
      if (users.size() == 3) {
        return Status::InvalidArgument(
            "mesh edge (" + std::to_string(key.first) + " " +
            std::to_string(key.second) + ") is shared by triangles " +
            std::to_string(users[0]) + ", " + std::to_string(users[1]) +
            " and " + std::to_string(users[2]) + " (not a manifold)");
      }
    }
  }
  for (const auto& [key, users] : edges) {
    AddSegment(t_.by_input_[key.first], t_.by_input_[key.second],
               ConstraintKind::kMesh,
               "mesh edge (" + std::to_string(key.first) + " " +
                   std::to_string(key.second) + ") of triangle " +
                   std::to_string(users[0]));
  }
  return Status::OK();
}

Status Triangulation::Builder::InsertConstraints() {
  Status s = InsertPolylines(c_.breaklines, false, ConstraintKind::kBreakline,
                             "breakline");
  if (s.ok()) {
    s = InsertPolylines(c_.rings, true, ConstraintKind::kRing, "ring");
  }
  if (s.ok()) {
    s = InsertPolylines(c_.segments, false, ConstraintKind::kSegment,
                        "segment");
  }
  if (s.ok()) s = InsertMeshEdges();
  return s;
}

Status Triangulation::Builder::NameCrossings() {
  // Which input segment claimed each crossing vertex first.
  std::map<Vertex_handle, size_t> claimed;
  for (size_t k = 0; k < segments_.size(); ++k) {
    const InputSegment& segment = segments_[k];
    const auto begin = dt_.vertices_in_constraint_begin(segment.id);
    const auto end = dt_.vertices_in_constraint_end(segment.id);
    const Vertex_handle a = *begin;
    const Vertex_handle b = *std::prev(end);
    for (auto it = begin; it != end; ++it) {
      const Vertex_handle v = *it;
      if (v->info().id >= 0 && !claimed.count(v)) continue;
      const auto [where, fresh] = claimed.emplace(v, k);
      if (fresh) {
        const double ab = Distance(FromCgal(a->point()), FromCgal(b->point()));
        const double av = Distance(FromCgal(a->point()), FromCgal(v->point()));
        const double w = ab > 0 ? std::min(1.0, av / ab) : 0.0;
        v->info() = VertexInfo{static_cast<int64_t>(t_.by_input_.size()),
                               (1 - w) * a->info().value + w * b->info().value};
        t_.by_input_.push_back(v);
        continue;
      }
      const InputSegment& other = segments_[where->second];
      if (IsBoundary(segment.kind) && IsBoundary(other.kind)) {
        return Status::InvalidArgument(
            other.name + " and " + segment.name + " cross at " +
            PointText(FromCgal(v->point())) +
            (segment.kind == ConstraintKind::kMesh
                 ? ": the mesh's triangles overlap"
                 : ": a domain boundary must not intersect itself"));
      }
    }
  }
  return Status::OK();
}

int Triangulation::Builder::RingCount(Face_handle f, int i) const {
  if (!f->is_constrained(i)) return 0;
  const Vertex_handle a = f->vertex(Cdt::cw(i));
  const Vertex_handle b = f->vertex(Cdt::ccw(i));
  int rings = 0;
  for (auto c = dt_.contexts_begin(a, b); c != dt_.contexts_end(a, b); ++c) {
    if (t_.constraint_kinds_.at(c->id()) == ConstraintKind::kRing) ++rings;
  }
  return rings;
}

bool Triangulation::Builder::IsBarrier(Face_handle f, int i) const {
  if (!f->is_constrained(i)) return false;
  const Vertex_handle a = f->vertex(Cdt::cw(i));
  const Vertex_handle b = f->vertex(Cdt::ccw(i));
  for (auto c = dt_.contexts_begin(a, b); c != dt_.contexts_end(a, b); ++c) {
    if (t_.constraint_kinds_.at(c->id()) != ConstraintKind::kBreakline) {
      return true;
    }
  }
  return false;
}

void Triangulation::Builder::MarkRingDepth() {
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    f->info() = -1;
  }
  // Flood each region at its depth; crossing a ring edge enters the region
  // beyond at depth + (rings along that edge). Regions are taken in the
  // order they are found, which is breadth-first by depth.
  std::deque<std::pair<Face_handle, int64_t>> regions;
  regions.emplace_back(dt_.infinite_face(), 0);
  std::vector<Face_handle> stack;
  while (!regions.empty()) {
    const auto [seed, depth] = regions.front();
    regions.pop_front();
    if (seed->info() != -1) continue;
    seed->info() = depth;
    stack.push_back(seed);
    while (!stack.empty()) {
      const Face_handle f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Face_handle n = f->neighbor(i);
        if (n->info() != -1) continue;
        const int rings = RingCount(f, i);
        if (rings > 0) {
          regions.emplace_back(n, depth + rings);
        } else {
          n->info() = depth;
          stack.push_back(n);
        }
      }
    }
  }
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    f->info() = dt_.is_infinite(f) ? 0 : f->info() % 2;
  }
}

void Triangulation::Builder::Eat(Face_handle seed) {
  std::vector<Face_handle> stack = {seed};
  seed->info() = 0;
  while (!stack.empty()) {
    const Face_handle f = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const Face_handle n = f->neighbor(i);
      if (n->info() == 0 || IsBarrier(f, i)) continue;
      n->info() = 0;
      stack.push_back(n);
    }
  }
}

Status Triangulation::Builder::EatSegmentRegions() {
  // Triangle's rule: what is reachable from outside the hull is out.
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    if (dt_.is_infinite(f)) {
      for (int i = 0; i < 3; ++i) {
        const Face_handle n = f->neighbor(i);
        if (!dt_.is_infinite(n) && n->info() != 0 && !IsBarrier(f, i)) Eat(n);
      }
    }
  }
  for (size_t k = 0; k < c_.hole_seeds.size(); ++k) {
    const Point2& p = c_.hole_seeds[k];
    const std::string name =
        "hole point " + std::to_string(k) + " " + PointText(p);
    if (!IsFinite(p)) {
      return Status::InvalidArgument(name + " has a non-finite coordinate");
    }
    const Face_handle f = dt_.locate(ToCgal(p));
    if (dt_.is_infinite(f) || f->info() == 0) {
      return Status::InvalidArgument(
          name +
          " is outside every region bounded by the rings and "
          "segments");
    }
    Eat(f);
  }
  return Status::OK();
}

Status Triangulation::Builder::MarkMesh() {
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    f->info() = 0;
  }
  for (size_t k = 0; k < c_.triangles.size(); ++k) {
    std::array<uint32_t, 3> ids;
    for (int i = 0; i < 3; ++i) {
      ids[i] =
          static_cast<uint32_t>(t_.by_input_[c_.triangles[k][i]]->info().id);
    }
    const auto& p = c_.triangles[k];
    if (CGAL::orientation(t_.by_input_[p[0]]->point(),
                          t_.by_input_[p[1]]->point(),
                          t_.by_input_[p[2]]->point()) == CGAL::CLOCKWISE) {
      std::swap(ids[1], ids[2]);
    }
    Face_handle f;
    const std::string name = "mesh triangle " + std::to_string(k) + " (" +
                             std::to_string(p[0]) + " " + std::to_string(p[1]) +
                             " " + std::to_string(p[2]) + ")";
    if (!t_.FaceWithCorners(ids, &f)) {
      return Status::InvalidArgument(
          name +
          " is not a face of the triangulation of the mesh's edges: "
          "it overlaps another triangle or contains a point");
    }
    if (f->info() == 1) {
      return Status::InvalidArgument(name + " repeats an earlier triangle");
    }
    f->info() = 1;
  }
  return Status::OK();
}

Status Triangulation::Builder::MarkDomain() {
  if (!c_.triangles.empty()) {
    t_.has_domain_ = true;
    return MarkMesh();
  }
  if (c_.rings.empty() && c_.segments.empty() && c_.hole_seeds.empty()) {
    for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
      f->info() = dt_.is_infinite(f) ? 0 : 1;
    }
    return Status::OK();
  }
  t_.has_domain_ = true;
  if (c_.rings.empty()) {
    for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
      f->info() = dt_.is_infinite(f) ? 0 : 1;
    }
  } else {
    MarkRingDepth();
  }
  if (c_.segments.empty() && c_.hole_seeds.empty()) return Status::OK();
  return EatSegmentRegions();
}

Status Triangulation::Builder::NumberTriangles() {
  int64_t next_id = 0;
  for (auto f = dt_.all_faces_begin(); f != dt_.all_faces_end(); ++f) {
    if (dt_.is_infinite(f) || f->info() != 1) f->info() = -1;
  }
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    if (f->info() == 1) f->info() = next_id++;
  }
  t_.num_triangles_ = static_cast<size_t>(next_id);
  if (next_id == 0) {
    return Status::InvalidArgument(
        "the domain is empty: no triangle is inside its boundary");
  }
  // Holes: regions of out-of-domain faces that do not reach the hull.
  std::map<Face_handle, bool> seen;
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    if (f->info() >= 0 || seen.count(f)) continue;
    bool touches_hull = false;
    std::vector<Face_handle> stack = {f};
    seen[f] = true;
    while (!stack.empty()) {
      const Face_handle g = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Face_handle n = g->neighbor(i);
        if (dt_.is_infinite(n)) {
          touches_hull = true;
        } else if (n->info() < 0 && !seen.count(n)) {
          seen[n] = true;
          stack.push_back(n);
        }
      }
    }
    if (!touches_hull) ++t_.num_holes_;
  }
  return Status::OK();
}

Status Triangulation::Build(const Dataset& dataset,
                            std::unique_ptr<Triangulation>* out) {
  std::unique_ptr<Triangulation> t(new Triangulation());
  Status s = Builder(dataset, t.get()).Run();
  if (!s.ok()) return s;
  *out = std::move(t);
  return Status::OK();
}

}  // namespace locator
