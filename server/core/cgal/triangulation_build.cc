// Triangulation::Build and its first steps: the points, the breaklines and
// rings, and the crossings between constraints (see triangulation_builder.h).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "common/input_text.h"
#include "common/status_macros.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/cgal/triangulation_builder.h"
#include "server/core/geometry/wide_math.h"
#include "server/core/tiling/build_checks.h"

namespace locator {

Status Triangulation::Builder::InsertPoints() {
  const std::vector<Point2>& pts = dataset_.points;
  const size_t n = pts.size();
  RETURN_IF_ERROR(CheckPointCoordinates(pts, dataset_.values.size()));

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

  const bool all_collinear =
      distinct.size() >= 3 &&
      std::all_of(distinct.begin() + 2, distinct.end(), [&](const auto& p) {
        return CGAL::orientation(distinct[0].first, distinct[1].first,
                                 p.first) == CGAL::COLLINEAR;
      });
  RETURN_IF_ERROR(CheckTriangulable(distinct.size(), all_collinear));

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
    const std::string name =
        line.name.empty() ? what + " " + std::to_string(l) : line.name;
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
      const std::string point =
          line.name.empty() ? name + " point " + std::to_string(k)
                            : "point " + std::to_string(k) + " of " + name;
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
      // "ring 0 segment 2", or after the source's own name: "segment 2 of
      // the exterior ring at a.wkt:3", and for a polyline of one segment (a
      // .poly segment) that name alone.
      const std::string segment =
          line.name.empty() ? name + " segment " + std::to_string(k)
          : segments == 1   ? name
                            : "segment " + std::to_string(k) + " of " + name;
      AddSegment(vertices[k], vertices[(k + 1) % vertices.size()], kind,
                 segment);
    }
  }
  return Status::OK();
}

Status Triangulation::Builder::InsertConstraints() {
  // CGAL computes where constraints cross in doubles, then widens the
  // point's box by a few ulps to snap it to a nearby end; a crossing that
  // overflowed, or lies within those ulps of +-DBL_MAX, makes that throw
  // (boost::math domain_error), so no crossing vertex is ever non-finite.
  try {
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
  } catch (const std::exception&) {
    return Status::InvalidArgument(
        "two constraints cross where the crossing point cannot be computed "
        "in doubles (coordinates too large)");
  }
}

Status Triangulation::Builder::NameCrossings() {
  // Which input segment claimed each crossing vertex first. A dataset point
  // inside a domain boundary segment (not one of its endpoints) is claimed
  // too, so that two boundaries crossing at a dataset point are caught like
  // those crossing anywhere else; boundaries may still touch at endpoints.
  std::map<Vertex_handle, size_t> claimed;
  for (size_t k = 0; k < segments_.size(); ++k) {
    const InputSegment& segment = segments_[k];
    // The hierarchy's vertex iterator only goes forwards.
    const std::vector<Vertex_handle> chain(
        dt_.vertices_in_constraint_begin(segment.id),
        dt_.vertices_in_constraint_end(segment.id));
    const Vertex_handle a = chain.front();
    const Vertex_handle b = chain.back();
    for (const Vertex_handle v : chain) {
      const bool created = v->info().id < 0;
      const bool inside_boundary = v != a && v != b && IsBoundary(segment.kind);
      if (!created && !inside_boundary) continue;
      const auto [where, fresh] = claimed.emplace(v, k);
      if (fresh && !created) continue;
      if (fresh) {
        // In Wide: the distances and the values may reach +-DBL_MAX.
        const Wide ab = Distance(FromCgal(a->point()), FromCgal(b->point()));
        const Wide av = Distance(FromCgal(a->point()), FromCgal(v->point()));
        const Wide w = ab > 0 ? std::min(Wide{1}, av / ab) : 0;
        v->info() = VertexInfo{static_cast<int64_t>(t_.by_input_.size()),
                               Lerp(a->info().value, b->info().value, w)};
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

StatusOr<std::unique_ptr<Triangulation>> Triangulation::Build(
    const Dataset& dataset) {
  std::unique_ptr<Triangulation> t(new Triangulation());
  RETURN_IF_ERROR(Builder(dataset, t.get()).Run());
  return t;
}

}  // namespace locator
