// SimplifyPoints (simplify_points.h): the skeleton (the convex hull's
// vertices and the constraints) triangulated by Triangulation::Build, which
// defines the domain; every other point bucketed in it; greedy insertion;
// then the certificate with the engine's own interpolation.

#include "server/core/terrain/points/simplify_points.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/status_macros.h"
#include "server/core/cgal/orientation.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/terrain/points/point_refiner.h"
#include "server/core/terrain/tin_mesh.h"
#include "server/core/terrain/tin_progress.h"

namespace locator {

namespace {

constexpr uint32_t kNone = 0xffffffffu;

Status CheckInput(const Dataset& in) {
  const size_t n = in.points.size();
  if (n == 0 || in.values.size() != n) {
    return Status::InvalidArgument(
        "max_error needs a value at every point: the dataset has " +
        std::to_string(n) + " points and " + std::to_string(in.values.size()) +
        " values");
  }
  if (!in.constraints.triangles.empty()) {
    return Status::InvalidArgument(
        "the dataset is a mesh given as triangles, which is served as given; "
        "max_error does not apply to it");
  }
  if (n > ServingMesh::kMaxElements) {
    return Status::InvalidArgument(
        "the dataset has " + std::to_string(n) + " points; at most " +
        std::to_string(ServingMesh::kMaxElements) + " can be simplified");
  }
  for (size_t i = 0; i < n; ++i) {
    if (!IsFinite(in.points[i])) {
      return Status::InvalidArgument("point " + std::to_string(i) +
                                     " has a non-finite coordinate");
    }
    if (!std::isfinite(in.values[i])) {
      return Status::InvalidArgument("the value of point " + std::to_string(i) +
                                     " is not finite");
    }
  }
  return Status::OK();
}

// The input's points by (x, y, index): runs of repeats, each led by its
// first occurrence.
class SortedPoints {
 public:
  explicit SortedPoints(const std::vector<Point2>& points) : points_(points) {
    order_.resize(points.size());
    for (uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    std::sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) {
      return std::tie(points[a].x, points[a].y, a) <
             std::tie(points[b].x, points[b].y, b);
    });
    for (uint32_t k = 0; k < order_.size(); ++k) {
      if (k == 0 || !Same(order_[k - 1], order_[k])) run_starts_.push_back(k);
    }
    run_starts_.push_back(static_cast<uint32_t>(order_.size()));
  }

  size_t runs() const { return run_starts_.size() - 1; }
  // Run r's points: order[begin(r)..end(r)); its first is its leader.
  uint32_t begin(size_t r) const { return run_starts_[r]; }
  uint32_t end(size_t r) const { return run_starts_[r + 1]; }
  uint32_t at(uint32_t k) const { return order_[k]; }
  uint32_t leader(size_t r) const { return order_[run_starts_[r]]; }
  // The leader of the run at p; kNone if no input point is at p.
  uint32_t Find(const Point2& p) const {
    const auto it =
        std::lower_bound(run_starts_.begin(), run_starts_.end() - 1, p,
                         [&](uint32_t k, const Point2& q) {
                           const Point2& a = points_[order_[k]];
                           return std::tie(a.x, a.y) < std::tie(q.x, q.y);
                         });
    if (it == run_starts_.end() - 1) return kNone;
    const Point2& a = points_[order_[*it]];
    return a.x == p.x && a.y == p.y ? order_[*it] : kNone;
  }

 private:
  bool Same(uint32_t a, uint32_t b) const {
    return points_[a].x == points_[b].x && points_[a].y == points_[b].y;
  }
  const std::vector<Point2>& points_;
  std::vector<uint32_t> order_;
  std::vector<uint32_t> run_starts_;
};

// The leaders of the convex hull's corners, counter-clockwise (Andrew's
// monotone chain over the runs in their (x, y) order; points on a hull
// edge are not corners). Fewer than 3 if all points are collinear.
std::vector<uint32_t> HullCorners(const std::vector<Point2>& points,
                                  const SortedPoints& sorted) {
  std::vector<uint32_t> hull;
  const size_t runs = sorted.runs();
  if (runs < 3) return hull;
  // Appends leader i, first dropping the corners it shows are not convex
  // (keeping at least `keep` points).
  const auto push = [&](uint32_t i, size_t keep) {
    while (hull.size() > keep &&
           Orientation(points[hull[hull.size() - 2]], points[hull.back()],
                       points[i]) != Side::kLeft) {
      hull.pop_back();
    }
    hull.push_back(i);
  };
  for (size_t r = 0; r < runs; ++r) push(sorted.leader(r), 1);
  const size_t lower = hull.size();
  for (size_t r = runs - 1; r-- > 0;) push(sorted.leader(r), lower);
  hull.pop_back();  // the first point again
  return hull;
}

// The skeleton: the hull's corners and the input points the constraints
// name, with the input's constraints, and which input point each is.
struct Skeleton {
  Dataset dataset;
  std::vector<uint32_t> input;  // skeleton point -> input point
};

Skeleton MakeSkeleton(const Dataset& in, const SortedPoints& sorted,
                      const std::vector<uint32_t>& hull) {
  Skeleton skeleton;
  std::vector<bool> added(in.points.size());
  const auto add = [&](uint32_t i) {
    if (i == kNone || added[i]) return;
    added[i] = true;
    skeleton.dataset.points.push_back(in.points[i]);
    skeleton.dataset.values.push_back(in.values[i]);
    skeleton.input.push_back(i);
  };
  for (const uint32_t i : hull) add(i);
  for (const auto* lines : {&in.constraints.breaklines, &in.constraints.rings,
                            &in.constraints.segments}) {
    for (const Polyline& line : *lines) {
      for (const Point2& p : line.points) {
        if (IsFinite(p)) add(sorted.Find(p));
      }
    }
  }
  skeleton.dataset.constraints = in.constraints;
  return skeleton;
}

// The TinMesh of a triangulation: every finite face, tagged 1 in the
// domain; vertex values and, per vertex, the input point it is (kNone for
// constraint points and crossings).
struct FirstMesh {
  TinMesh mesh{TinMesh::Coordinates::kAnyDouble};
  std::vector<double> values;
  std::vector<uint32_t> input;
  std::vector<uint32_t> vertex_of_id;      // stable id -> mesh vertex
  std::vector<uint32_t> triangle_of_face;  // Triangulation::MeshFace -> mesh
};

void ConvertSkeleton(const Triangulation& t, const Skeleton& skeleton,
                     FirstMesh* out) {
  const Triangulation::Cdt& cdt = t.cgal();
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end();
       ++v) {
    const auto id = static_cast<size_t>(v->info().id);
    if (id >= out->vertex_of_id.size()) out->vertex_of_id.resize(id + 1, kNone);
    out->vertex_of_id[id] =
        out->mesh.AddVertex(Triangulation::FromCgal(v->point()));
    out->values.push_back(v->info().value);
    out->input.push_back(id < skeleton.input.size() ? skeleton.input[id]
                                                    : kNone);
  }
  out->triangle_of_face.assign(t.num_faces(), kNone);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    std::array<uint32_t, 3> c;
    for (int i = 0; i < 3; ++i) {
      c[i] = out->vertex_of_id[static_cast<size_t>(f->vertex(i)->info().id)];
    }
    out->triangle_of_face[t.MeshFace(f)] =
        out->mesh.AddTriangle(c[0], c[1], c[2], t.InDomain(f) ? 1 : 0);
  }
  // CGAL's edge i is opposite vertex i: the half-edge from corner i + 1.
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const uint32_t a = out->triangle_of_face[t.MeshFace(f)];
    for (int i = 0; i < 3; ++i) {
      const Triangulation::Face_handle n = f->neighbor(i);
      if (t.IsInfinite(n)) continue;
      const uint32_t b = out->triangle_of_face[t.MeshFace(n)];
      if (b < a) continue;  // linked from n
      const uint32_t h = 3 * a + (i + 1) % 3;
      out->mesh.Link(h, 3 * b + (n->index(f) + 1) % 3);
      if (f->is_constrained(i)) out->mesh.Constrain(h);
    }
  }
}

}  // namespace

Status SimplifyPoints(const Dataset& in, const TinOptions& options,
                      Dataset* out, SimplificationStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  RETURN_IF_ERROR(CheckTinOptions(options));
  RETURN_IF_ERROR(CheckInput(in));
  const SortedPoints sorted(in.points);
  const std::vector<uint32_t> hull = HullCorners(in.points, sorted);
  if (hull.size() < 3) {
    return Status::InvalidArgument(
        "the dataset's " + std::to_string(sorted.runs()) +
        " distinct points are collinear or fewer than 3: no triangle can be "
        "formed");
  }
  const Skeleton skeleton = MakeSkeleton(in, sorted, hull);
  ASSIGN_OR_RETURN(std::unique_ptr<Triangulation> t,
                   Triangulation::Build(skeleton.dataset));
  FirstMesh first;
  ConvertSkeleton(*t, skeleton, &first);
  if (options.max_points > 0 &&
      first.mesh.num_vertices() > options.max_points) {
    return Status::InvalidArgument(
        "max_points is " + std::to_string(options.max_points) +
        "; the hull and the constraints alone need " +
        std::to_string(first.mesh.num_vertices()) + " vertices");
  }
  *stats = SimplificationStats();
  stats->source_samples = in.points.size();
  stats->target_error = options.max_error;
  stats->max_points = options.max_points;

  PointRefiner refiner(in.points, in.values, &first.mesh, &first.values,
                       options.max_error);
  std::vector<uint32_t> skeleton_vertex(in.points.size(), kNone);
  for (uint32_t v = 0; v < first.input.size(); ++v) {
    if (first.input[v] != kNone) skeleton_vertex[first.input[v]] = v;
  }
  Triangulation::Face_handle hint;
  for (size_t r = 0; r < sorted.runs(); ++r) {
    const uint32_t leader = sorted.leader(r);
    double lo = in.values[leader], hi = lo;
    for (uint32_t k = sorted.begin(r); k < sorted.end(r); ++k) {
      lo = std::min(lo, in.values[sorted.at(k)]);
      hi = std::max(hi, in.values[sorted.at(k)]);
    }
    if (skeleton_vertex[leader] != kNone) {
      refiner.AddAtVertex(skeleton_vertex[leader], lo, hi);
      continue;
    }
    Triangulation::Cdt::Locate_type type;
    int li = 0;
    Triangulation::Face_handle f = t->cgal().locate(
        Triangulation::ToCgal(in.points[leader]), type, li, hint);
    hint = f;
    if (type == Triangulation::Cdt::VERTEX) {  // a crossing's vertex
      refiner.AddAtVertex(
          first.vertex_of_id[static_cast<size_t>(f->vertex(li)->info().id)], lo,
          hi);
      continue;
    }
    if (type == Triangulation::Cdt::EDGE && !t->InDomain(f) &&
        !t->IsInfinite(f->neighbor(li)) && t->InDomain(f->neighbor(li))) {
      f = f->neighbor(li);  // on the domain's boundary: served from inside
    }
    if (type != Triangulation::Cdt::FACE && type != Triangulation::Cdt::EDGE) {
      return Status::Internal("a point is outside the hull of its dataset");
    }
    if (t->IsInfinite(f) || !t->InDomain(f)) {
      stats->unserved_samples += sorted.end(r) - sorted.begin(r);
      continue;
    }
    refiner.Add(leader, first.triangle_of_face[t->MeshFace(f)]);
    if (sorted.end(r) - sorted.begin(r) > 1) refiner.SetRepeats(leader, lo, hi);
  }
  t.reset();

  TinProgressReporter progress(options, 1);
  refiner.ScanAll(PointMeasure::kFace);
  RETURN_IF_ERROR(refiner.Refine(options.max_points, &progress));
  // The engine's own interpolation; points it finds beyond the target
  // differ from the build's measure by rounding only.
  refiner.ScanAll(PointMeasure::kServed);
  RETURN_IF_ERROR(refiner.Refine(options.max_points, &progress));
  stats->max_error = refiner.MaxError();

  // Kept input points in input order, then the constraints' own points.
  const TinMesh& mesh = first.mesh;
  std::vector<std::pair<uint64_t, uint32_t>> order(mesh.num_vertices());
  for (uint32_t v = 0; v < mesh.num_vertices(); ++v) {
    const uint32_t input =
        v < refiner.first_inserted()
            ? first.input[v]
            : refiner.inserted()[v - refiner.first_inserted()];
    order[v] = {input != kNone ? input : in.points.size() + v, v};
  }
  std::sort(order.begin(), order.end());
  std::vector<uint32_t> id(mesh.num_vertices());
  *out = Dataset();
  out->crs = in.crs;
  out->source = in.source;
  for (const auto& [key, v] : order) {
    id[v] = static_cast<uint32_t>(out->points.size());
    out->points.push_back(mesh.point(v));
    out->values.push_back(first.values[v]);
  }
  for (uint32_t tri = 0; tri < mesh.num_triangles(); ++tri) {
    if (mesh.tag(tri) != 1) continue;
    out->constraints.triangles.push_back({id[mesh.Corner(tri, 0)],
                                          id[mesh.Corner(tri, 1)],
                                          id[mesh.Corner(tri, 2)]});
  }
  RecordTinMade(*out, start, stats);
  return Status::OK();
}

}  // namespace locator
