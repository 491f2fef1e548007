#include "server/core/mesh/serving_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_set>
#include <utility>
#include <vector>

#include "common/hilbert.h"
#include "server/core/cgal/orientation.h"
#include "server/core/geometry/barycentric.h"
#include "server/core/geometry/segment_distance.h"
#include "server/core/geometry/wide_math.h"

namespace locator {

namespace {

// A candidate edge for "nearest": its squared distance, then its endpoints'
// public ids (smaller first) to break ties the same way wherever it is found.
struct EdgeKey {
  long double distance = std::numeric_limits<long double>::infinity();
  std::pair<int64_t, int64_t> ids{-1, -1};
  bool operator<(const EdgeKey& o) const {
    return distance < o.distance || (distance == o.distance && ids < o.ids);
  }
};

}  // namespace

ServingMesh::ServingMesh(std::unique_ptr<const Storage> storage,
                         const Arrays& arrays)
    : storage_(std::move(storage)), a_(arrays) {}

uint64_t ServingMesh::id_bound() const {
  std::call_once(id_bound_once_, [this] {
    id_bound_ = a_.input_points;
    for (const uint32_t id : a_.ids) {
      id_bound_ = std::max<uint64_t>(id_bound_, uint64_t{id} + 1);
    }
  });
  return id_bound_;
}

std::array<uint32_t, 3> ServingMesh::CornerIds(uint32_t f) const {
  return {a_.ids[Corner(f, 0)], a_.ids[Corner(f, 1)], a_.ids[Corner(f, 2)]};
}

std::vector<std::array<Point2, 2>> ServingMesh::SampleEdges(
    size_t max_edges) const {
  std::vector<std::array<Point2, 2>> sample;
  if (max_edges == 0) return sample;
  // Euler's formula for a triangulated point set: V - E + (F + 1) = 2.
  const size_t edges = num_vertices() + num_faces() - 1;
  const size_t stride = (edges + max_edges - 1) / max_edges;
  sample.reserve(std::min(edges, max_edges));
  size_t index = 0;
  for (uint32_t f = 0; f < num_faces(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t n = Neighbor(f, i);
      if (!IsHull(n) && n < f) continue;  // counted from n
      if (index++ % stride != 0) continue;
      sample.push_back({CornerPoint(f, Ccw(i)), CornerPoint(f, Cw(i))});
    }
  }
  return sample;
}

size_t ServingMesh::MemoryBytes() const {
  return a_.triangles.size_bytes() + a_.points.size_bytes() +
         a_.values.size_bytes() + a_.ids.size_bytes() + a_.hull.size_bytes();
}

uint32_t ServingMesh::CentroidKey(const Point2& a, const Point2& b,
                                  const Point2& c, const BoundingBox& box) {
  Point2 centroid{0, 0};
  for (const Point2* p : {&a, &b, &c}) {
    centroid.x += p->x / 3;
    centroid.y += p->y / 3;
  }
  return HilbertKey(centroid, box);
}

uint32_t ServingMesh::TriangleNear(const Point2& q) const {
  const uint32_t key = HilbertKey(q, a_.box);
  uint32_t lo = 0;
  uint32_t hi = a_.in_domain;  // the first triangle whose key is >= key
  while (lo < hi) {
    const uint32_t mid = lo + (hi - lo) / 2;
    if (CentroidKey(CornerPoint(mid, 0), CornerPoint(mid, 1),
                    CornerPoint(mid, 2), a_.box) < key) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return std::min(lo, a_.in_domain - 1);
}

void ServingMesh::NearestVisibleHullEdge(uint32_t* face, int* edge,
                                         const Point2& q) const {
  const auto key = [&](uint32_t f, int i) {
    const uint32_t a = Corner(f, Ccw(i));
    const uint32_t b = Corner(f, Cw(i));
    return EdgeKey{SegmentDistance2(a_.points[a], a_.points[b], q),
                   std::minmax<int64_t>(a_.ids[a], a_.ids[b])};
  };
  const size_t ring = a_.hull.size();
  const size_t exit = Neighbor(*face, *edge) & kIndexMask;
  EdgeKey best = key(*face, *edge);
  for (const size_t step : {size_t{1}, ring - 1}) {
    for (size_t pos = (exit + step) % ring; pos != exit;
         pos = (pos + step) % ring) {
      const uint32_t f = EdgeFace(a_.hull[pos]);
      const int i = EdgeIndex(a_.hull[pos]);
      if (Orientation(CornerPoint(f, Ccw(i)), CornerPoint(f, Cw(i)), q) !=
          Side::kRight) {
        break;
      }
      const EdgeKey k = key(f, i);
      if (k < best) {
        best = k;
        *face = f;
        *edge = i;
      }
    }
  }
}

bool ServingMesh::MoveIntoDomain(uint32_t* f, LocationType type,
                                 int* feature) const {
  if (type == LocationType::kEdge) {
    const uint32_t n = Neighbor(*f, *feature);
    if (IsHull(n) || !InDomain(n)) return false;
    *feature = MirrorIndex(n, *f);
    *f = n;
    return true;
  }
  if (type != LocationType::kVertex) return false;
  const uint32_t v = Corner(*f, *feature);
  uint32_t found = kNoFace;
  if (!AnyFaceAround(*f, v, [&](uint32_t g) {
        found = g;
        return InDomain(g);
      })) {
    return false;
  }
  *f = found;
  *feature = IndexOf(found, v);
  return true;
}

std::vector<uint32_t> ServingMesh::FacesWithCorners(
    std::span<const std::array<uint32_t, 3>> ids) const {
  std::vector<uint32_t> faces(ids.size(), kNoFace);
  if (ids.empty()) return faces;
  std::vector<uint32_t> vertex_of_id;
  for (uint32_t v = 0; v < a_.ids.size(); ++v) {
    if (a_.ids[v] >= vertex_of_id.size()) {
      vertex_of_id.resize(a_.ids[v] + 1, kNoFace);
    }
    vertex_of_id[a_.ids[v]] = v;
  }
  std::vector<uint32_t> face_at(a_.points.size());
  for (uint32_t f = 0; f < a_.triangles.size(); ++f) {
    for (int i = 0; i < 3; ++i) face_at[Corner(f, i)] = f;
  }
  const auto vertex = [&](uint32_t id) {
    return id < vertex_of_id.size() ? vertex_of_id[id] : kNoFace;
  };
  for (size_t k = 0; k < ids.size(); ++k) {
    const std::array<uint32_t, 3> v = {vertex(ids[k][0]), vertex(ids[k][1]),
                                       vertex(ids[k][2])};
    if (v[0] == kNoFace || v[1] == kNoFace || v[2] == kNoFace) continue;
    const auto matches = [&](uint32_t g) {
      const int j = IndexOf(g, v[0]);
      if (Corner(g, Ccw(j)) != v[1] || Corner(g, Cw(j)) != v[2]) return false;
      faces[k] = g;
      return true;
    };
    const uint32_t first = face_at[v[0]];
    if (!matches(first)) AnyFaceAround(first, v[0], matches);
  }
  return faces;
}

void ServingMesh::DescribeOutsideDomain(uint32_t f, const Point2& q,
                                        LocateResult* out) const {
  *out = LocateResult();
  out->type = LocationType::kOutsideDomain;
  // Best-first over the out-of-domain faces by their distance to q: the
  // segment from q to the nearest boundary point stays outside the domain,
  // so the search stops once no face is nearer than the best edge found.
  EdgeKey best;
  const auto edge_distance = [&](uint32_t g, int i) {
    return SegmentDistance2(CornerPoint(g, Ccw(i)), CornerPoint(g, Cw(i)), q);
  };
  using Entry = std::pair<long double, uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> frontier;
  std::unordered_set<uint32_t> seen{f};
  frontier.emplace(0.0L, f);
  while (!frontier.empty() && frontier.top().first <= best.distance) {
    const uint32_t g = frontier.top().second;
    frontier.pop();
    for (int i = 0; i < 3; ++i) {
      const uint32_t n = Neighbor(g, i);
      if (IsHull(n)) continue;
      if (InDomain(n)) {
        best = std::min(
            best, EdgeKey{edge_distance(g, i),
                          std::minmax<int64_t>(a_.ids[Corner(g, Ccw(i))],
                                               a_.ids[Corner(g, Cw(i))])});
      } else if (seen.insert(n).second) {
        const int j = MirrorIndex(n, g);
        const long double d =
            std::min({edge_distance(g, i), edge_distance(n, Ccw(j)),
                      edge_distance(n, Cw(j))});
        frontier.emplace(d, n);
      }
    }
  }
  out->domain_edge_ids = {best.ids.first, best.ids.second};
}

void ServingMesh::Describe(uint32_t f, LocationType type, int feature,
                           const Point2& q, LocateResult* out,
                           Detail detail) const {
  if (type != LocationType::kOutsideConvexHull && !InDomain(f) &&
      !MoveIntoDomain(&f, type, &feature)) {
    DescribeOutsideDomain(f, q, out);
    return;
  }
  out->type = type;
  out->triangle_id = InDomain(f) ? int64_t{f} : int64_t{-1};
  for (int i = 0; i < 3; ++i) {
    const uint32_t v = Corner(f, i);
    out->vertex_ids[i] = a_.ids[v];
    out->vertices[i] = a_.points[v];
  }
  out->feature_index =
      static_cast<int8_t>(type == LocationType::kFace ? -1 : feature);
  out->hull_edge_ids = {-1, -1};
  out->domain_edge_ids = {-1, -1};
  out->has_value = false;
  out->value = 0;
  out->barycentric = {0, 0, 0};
  if (type == LocationType::kOutsideConvexHull) {
    out->hull_edge_ids = {out->vertex_ids[Ccw(feature)],
                          out->vertex_ids[Cw(feature)]};
    return;
  }
  if (detail == Detail::kLocation) return;
  switch (type) {
    case LocationType::kOutsideConvexHull:
    case LocationType::kOutsideDomain:
      return;  // handled above
    case LocationType::kVertex:
      out->barycentric[feature] = 1;
      break;
    case LocationType::kEdge:
      out->barycentric = EdgeBarycentric(out->vertices, feature, q);
      break;
    case LocationType::kFace:
      out->barycentric =
          Barycentric(out->vertices[0], out->vertices[1], out->vertices[2], q);
      break;
  }
  if (has_values()) {
    out->has_value = true;
    if (detail == Detail::kFull) out->value = CornerValue(f, out->barycentric);
  }
}

double ServingMesh::CornerValue(uint32_t f,
                                const std::array<double, 3>& b) const {
  double value = 0;
  for (int i = 0; i < 3; ++i) value += b[i] * a_.values[Corner(f, i)];
  if (std::isfinite(value)) [[likely]] {
    return value;
  }
  // Values near +-DBL_MAX overflowed the double sum.
  ConvexSum wide;
  for (int i = 0; i < 3; ++i) wide.Add(b[i], a_.values[Corner(f, i)]);
  return wide.value();
}

}  // namespace locator
