#include "server/core/patch/simplify_clipped_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <iterator>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

#include "server/core/cgal/cdt_with_info.h"

namespace locator {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

struct VertexInfo {
  uint32_t index = kNone;  // in the input mesh; kNone: made by CGAL
};
struct FaceInfo {
  bool inside = false;            // in the footprint
  std::vector<uint32_t> waiting;  // vertices not inserted that lie in it
};
// Constraints never cross in a clipped TIN; if they do (a patch that was no
// planar mesh), CGAL throws instead of guessing the crossing.
using Cdt =
    CdtWithInfo<VertexInfo, FaceInfo, CGAL::No_constraint_intersection_tag>;
using Face_handle = Cdt::Face_handle;
using Vertex_handle = Cdt::Vertex_handle;

uint64_t EdgeKey(uint32_t a, uint32_t b) {
  return (uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// The boundary edges of `mesh` (those of one triangle), by EdgeKey, and
// how many each vertex has.
struct Boundary {
  std::unordered_map<uint64_t, std::pair<uint32_t, uint32_t>> edges;
  std::vector<uint32_t> degree;
};

Boundary BoundaryOf(const ClippedMesh& mesh) {
  // Every edge of every triangle, sorted by EdgeKey: an edge of one
  // triangle stands alone (an interior edge comes twice).
  struct HalfEdge {
    uint64_t key;
    uint32_t from, to;
  };
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t u = t[i], v = t[(i + 1) % 3];
      half_edges.push_back({EdgeKey(u, v), u, v});
    }
  }
  std::sort(half_edges.begin(), half_edges.end(),
            [](const HalfEdge& a, const HalfEdge& b) { return a.key < b.key; });
  Boundary b;
  b.degree.assign(mesh.size(), 0);
  for (size_t i = 0; i < half_edges.size(); ++i) {
    const bool alone = (i == 0 || half_edges[i - 1].key != half_edges[i].key) &&
                       (i + 1 == half_edges.size() ||
                        half_edges[i + 1].key != half_edges[i].key);
    if (!alone) continue;
    const HalfEdge& e = half_edges[i];
    b.edges.emplace(e.key, std::pair(e.from, e.to));
    ++b.degree[e.from];
    ++b.degree[e.to];
  }
  return b;
}

// Douglas-Peucker over run[first..last] by (position along the side,
// height): marks in `keep` the vertices the run needs to stay within
// `tolerance` of its heights.
void KeepAlongSide(const ClippedMesh& mesh, const std::vector<uint32_t>& run,
                   size_t first, size_t last, bool vertical, double tolerance,
                   std::vector<bool>* keep) {
  if (last - first < 2) return;
  const auto along = [&](uint32_t v) {
    return vertical ? mesh.points[v].y : mesh.points[v].x;
  };
  const double s0 = along(run[first]), s1 = along(run[last]);
  const double h0 = mesh.heights[run[first]], h1 = mesh.heights[run[last]];
  size_t worst = first;
  double worst_error = -1;
  for (size_t i = first + 1; i < last; ++i) {
    const double t = (along(run[i]) - s0) / (s1 - s0);
    const double error = std::abs(mesh.heights[run[i]] - (h0 + t * (h1 - h0)));
    if (error > worst_error) worst = i, worst_error = error;
  }
  if (worst_error <= tolerance) return;
  (*keep)[run[worst]] = true;
  KeepAlongSide(mesh, run, first, worst, vertical, tolerance, keep);
  KeepAlongSide(mesh, run, worst, last, vertical, tolerance, keep);
}

// Which vertices the simplified mesh keeps before refining: every
// boundary vertex but those inside a run along a box side that
// Douglas-Peucker drops; and the constraints between kept ones.
void KeptBoundary(const ClippedMesh& mesh, const Boundary& boundary,
                  double tolerance, std::vector<bool>* keep,
                  std::vector<std::pair<uint32_t, uint32_t>>* constraints) {
  keep->assign(mesh.size(), false);
  for (const auto& [key, edge] : boundary.edges) {
    (*keep)[edge.first] = (*keep)[edge.second] = true;
  }
  for (BoxSide side : {kWestSide, kSouthSide, kEastSide, kNorthSide}) {
    const bool vertical = side == kWestSide || side == kEastSide;
    std::vector<uint32_t> on_side;
    for (uint32_t v = 0; v < mesh.size(); ++v) {
      if (mesh.sides[v] & side) on_side.push_back(v);
    }
    std::sort(on_side.begin(), on_side.end(), [&](uint32_t a, uint32_t b) {
      return vertical ? mesh.points[a].y < mesh.points[b].y
                      : mesh.points[a].x < mesh.points[b].x;
    });
    // Runs: stretches joined by boundary edges along the side. A vertex
    // inside a run with more boundary edges than the two along the side
    // (where the footprint's boundary leaves the side) is kept regardless.
    size_t start = 0;
    for (size_t i = 1; i <= on_side.size(); ++i) {
      if (i < on_side.size() &&
          boundary.edges.contains(EdgeKey(on_side[i - 1], on_side[i]))) {
        continue;
      }
      if (i - start >= 2) {
        std::vector<uint32_t> run(on_side.begin() + start, on_side.begin() + i);
        for (size_t k = 1; k + 1 < run.size(); ++k) {
          (*keep)[run[k]] = boundary.degree[run[k]] != 2;
        }
        KeepAlongSide(mesh, run, 0, run.size() - 1, vertical, tolerance, keep);
        uint32_t previous = run[0];
        for (size_t k = 1; k < run.size(); ++k) {
          if (!(*keep)[run[k]]) continue;
          constraints->emplace_back(previous, run[k]);
          previous = run[k];
        }
      }
      start = i;
    }
  }
  for (const auto& [key, edge] : boundary.edges) {
    const auto [u, v] = edge;
    const uint8_t common = mesh.sides[u] & mesh.sides[v];
    if (common == 0) constraints->emplace_back(u, v);  // not along a side
  }
}

// Marks the faces inside the constraints' rings (odd nesting), as CGAL's
// polygon-with-holes example does.
void MarkInside(Cdt* cdt) {
  std::vector<std::pair<Face_handle, int>> queue = {{cdt->infinite_face(), 0}};
  for (auto f = cdt->all_faces_begin(); f != cdt->all_faces_end(); ++f) {
    f->info().inside = false;
  }
  std::unordered_map<Face_handle, int, CGAL::Handle_hash_function> level;
  level[cdt->infinite_face()] = 0;
  while (!queue.empty()) {
    const auto [f, nesting] = queue.back();
    queue.pop_back();
    f->info().inside = nesting % 2 == 1;
    for (int i = 0; i < 3; ++i) {
      const Face_handle n = f->neighbor(i);
      if (level.contains(n)) continue;
      const int next = cdt->is_constrained({f, i}) ? nesting + 1 : nesting;
      level[n] = next;
      queue.emplace_back(n, next);
    }
  }
}

class Refiner {
 public:
  Refiner(const ClippedMesh& mesh, double x_scale)
      : mesh_(mesh), x_scale_(x_scale), version_(mesh.size(), 0) {}

  Cdt::Point At(uint32_t v) const {
    return {mesh_.points[v].x * x_scale_, mesh_.points[v].y};
  }

  // The height error of waiting vertex v in face f.
  double Error(Face_handle f, uint32_t v) const {
    const Cdt::Point q = At(v);
    const auto& a = f->vertex(0)->point();
    const auto& b = f->vertex(1)->point();
    const auto& c = f->vertex(2)->point();
    const double ha = mesh_.heights[f->vertex(0)->info().index];
    const double hb = mesh_.heights[f->vertex(1)->info().index];
    const double hc = mesh_.heights[f->vertex(2)->info().index];
    const double det =
        (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    const double s = ((q.x() - a.x()) * (c.y() - a.y()) -
                      (c.x() - a.x()) * (q.y() - a.y())) /
                     det;
    const double t = ((b.x() - a.x()) * (q.y() - a.y()) -
                      (q.x() - a.x()) * (b.y() - a.y())) /
                     det;
    return std::abs(mesh_.heights[v] - (ha + s * (hb - ha) + t * (hc - ha)));
  }

  // Puts waiting vertex v into the face that holds it; returns the face.
  // Queue the face's worst vertex (Enqueue) once its vertices are in.
  Face_handle Wait(Cdt* cdt, uint32_t v, Face_handle hint) {
    const Face_handle f = cdt->locate(At(v), hint);
    ++version_[v];
    if (cdt->is_infinite(f) || !f->info().inside) {
      // Rounding put it outside: insert it first, as it is data.
      queue_.push({std::numeric_limits<double>::infinity(), v, version_[v]});
      return f;
    }
    f->info().waiting.push_back(v);
    return f;
  }

  // Queues the vertex of f farthest from its plane: the one a face can
  // need next. The queue holds one entry per face, not per vertex; an
  // entry goes stale when its vertex moves to another face.
  void Enqueue(Face_handle f) {
    double worst_error = -1;
    uint32_t worst = kNone;
    for (uint32_t v : f->info().waiting) {
      const double error = Error(f, v);
      if (error > worst_error) worst = v, worst_error = error;
    }
    if (worst != kNone) queue_.push({worst_error, worst, version_[worst]});
  }

  // Inserts the farthest vertex while one is farther than `tolerance`.
  void Run(Cdt* cdt, double tolerance) {
    std::vector<Face_handle> conflicts, touched;
    while (!queue_.empty()) {
      const Entry top = queue_.top();
      queue_.pop();
      if (top.version != version_[top.v]) continue;
      if (!(top.error > tolerance)) break;
      ++version_[top.v];  // inserted: no longer waiting
      conflicts.clear();
      cdt->get_conflicts(At(top.v), std::back_inserter(conflicts));
      // None: a vertex already there (at the same place); nothing to add.
      if (conflicts.empty()) continue;
      // The conflict zone never crosses a constraint: all one side.
      const bool inside = conflicts.front()->info().inside;
      std::vector<uint32_t> moved;
      for (Face_handle f : conflicts) {
        for (uint32_t v : f->info().waiting) {
          if (v != top.v) moved.push_back(v);
        }
      }
      const Vertex_handle vh = cdt->insert(At(top.v));
      vh->info().index = top.v;
      touched.clear();
      auto f = cdt->incident_faces(vh), done = f;
      do {
        f->info().waiting.clear();
        f->info().inside = inside;
        touched.push_back(f);
      } while (++f != done);
      Face_handle hint = vh->face();
      for (uint32_t v : moved) {
        hint = Wait(cdt, v, hint);
        touched.push_back(hint);
      }
      std::sort(touched.begin(), touched.end());
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
      for (Face_handle t : touched) {
        if (!cdt->is_infinite(t) && t->info().inside) Enqueue(t);
      }
    }
  }

 private:
  struct Entry {
    double error;
    uint32_t v;
    uint32_t version;
    bool operator<(const Entry& o) const { return error < o.error; }
  };
  const ClippedMesh& mesh_;
  const double x_scale_;
  std::vector<uint32_t> version_;
  std::priority_queue<Entry> queue_;
};

}  // namespace

namespace {

// SimplifyClippedMesh, where CGAL may throw.
ClippedMesh Simplify(const ClippedMesh& mesh, double tolerance,
                     double x_scale) {
  const Boundary boundary = BoundaryOf(mesh);
  std::vector<bool> keep;
  std::vector<std::pair<uint32_t, uint32_t>> constraints;
  KeptBoundary(mesh, boundary, tolerance, &keep, &constraints);
  Refiner refiner(mesh, x_scale);
  Cdt cdt;
  std::vector<Vertex_handle> handle(mesh.size());
  for (uint32_t v = 0; v < mesh.size(); ++v) {
    if (!keep[v]) continue;
    handle[v] = cdt.insert(refiner.At(v));
    handle[v]->info().index = v;
  }
  for (const auto& [u, v] : constraints) {
    // Two vertices at one place share a handle: no edge between them.
    if (handle[u] == Vertex_handle() || handle[v] == Vertex_handle()) {
      return mesh;  // an edge to a vertex that was dropped: no plain mesh
    }
    if (handle[u] != handle[v]) cdt.insert_constraint(handle[u], handle[v]);
  }
  MarkInside(&cdt);
  // The vertices come in the patch's order, near one another: each
  // locate starts from the face of the one before.
  Face_handle hint;
  for (uint32_t v = 0; v < mesh.size(); ++v) {
    if (!keep[v] && mesh.sides[v] == 0 && boundary.degree[v] == 0) {
      hint = refiner.Wait(&cdt, v, hint);
    }
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().inside) refiner.Enqueue(f);
  }
  refiner.Run(&cdt, tolerance);

  ClippedMesh out;
  std::vector<uint32_t> index_of(mesh.size(), kNone);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->info().inside) continue;
    std::array<uint32_t, 3> t;
    for (int i = 0; i < 3; ++i) {
      const uint32_t v = f->vertex(i)->info().index;
      if (index_of[v] == kNone) {
        index_of[v] = static_cast<uint32_t>(out.size());
        out.points.push_back(mesh.points[v]);
        out.heights.push_back(mesh.heights[v]);
        out.sides.push_back(mesh.sides[v]);
      }
      t[i] = index_of[v];
    }
    out.triangles.push_back(t);
  }
  return out;
}

}  // namespace

ClippedMesh SimplifyClippedMesh(const ClippedMesh& mesh, double tolerance,
                                double x_scale) {
  if (mesh.triangles.empty()) return mesh;
  try {
    return Simplify(mesh, tolerance, x_scale);
  } catch (const std::exception&) {
    // Crossing constraints (a patch that was no planar mesh): the mesh as
    // it came, which is still the patch's surface.
    return mesh;
  }
}

}  // namespace locator
