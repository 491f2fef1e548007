#include "server/core/cgal/triangulation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <string>
#include <unordered_set>
#include <utility>

#include "server/core/geometry/barycentric.h"
#include "server/core/geometry/segment_distance.h"
#include "server/core/geometry/xxh3_digest.h"

namespace locator {

namespace {

bool Contains(const std::array<int64_t, 3>& ids, int64_t id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

}  // namespace

size_t Triangulation::MemoryBytes() const {
  return dt_.tds().vertices().capacity() * sizeof(Tds::Vertex) +
         dt_.tds().faces().capacity() * sizeof(Tds::Face) +
         by_input_.capacity() * sizeof(Vertex_handle);
}

bool Triangulation::VertexPoint(int64_t id, Point2* p) const {
  if (id < 0 || static_cast<size_t>(id) >= by_input_.size()) return false;
  const Vertex_handle v = by_input_[id];
  if (v->info().id != id) return false;  // merged into an earlier point
  *p = FromCgal(v->point());
  return true;
}

Triangulation::Face_handle Triangulation::FiniteFaceAt(Vertex_handle v) const {
  auto fc = dt_.incident_faces(v);
  while (dt_.is_infinite(fc)) ++fc;
  return fc;
}

Triangulation::Face_handle Triangulation::DefaultStart() const {
  const Face_handle inf = dt_.infinite_face();
  return inf->neighbor(inf->index(dt_.infinite_vertex()));
}

uint64_t Triangulation::VertexDigest() const {
  Xxh3Digest hash;
  for (size_t id = 0; id < by_input_.size(); ++id) {
    const Vertex_handle v = by_input_[id];
    if (static_cast<size_t>(v->info().id) != id) continue;  // merged
    hash.AddU64(id);
    hash.AddDouble(v->point().x());
    hash.AddDouble(v->point().y());
  }
  if (num_constraints() == 0 && !has_domain_) return hash.digest();
  // The constrained edges and the in-domain triangles, by sorted ids.
  std::vector<std::array<int64_t, 3>> items;
  for (auto e = dt_.finite_edges_begin(); e != dt_.finite_edges_end(); ++e) {
    if (!dt_.is_constrained(*e)) continue;
    const auto [a, b] = std::minmax(e->first->vertex(Ccw(e->second))->info().id,
                                    e->first->vertex(Cw(e->second))->info().id);
    items.push_back({-1, a, b});
  }
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    if (!InDomain(f)) continue;
    std::array<int64_t, 3> ids = {f->vertex(0)->info().id,
                                  f->vertex(1)->info().id,
                                  f->vertex(2)->info().id};
    std::sort(ids.begin(), ids.end());
    items.push_back(ids);
  }
  std::sort(items.begin(), items.end());
  for (const auto& item : items) {
    for (const int64_t id : item) hash.AddU64(static_cast<uint64_t>(id));
  }
  return hash.digest();
}

int Triangulation::MeshIndex(Face_handle f, int i) const {
  const int64_t id = f->vertex(i)->info().id;
  const std::array<uint32_t, 3> ids = mesh_->CornerIds(MeshFace(f));
  return ids[0] == id ? 0 : ids[1] == id ? 1 : 2;
}

std::array<uint32_t, 3> Triangulation::CornerIds(Face_handle f) const {
  std::array<uint32_t, 3> ids;
  for (int i = 0; i < 3; ++i) {
    ids[i] = static_cast<uint32_t>(f->vertex(i)->info().id);
  }
  return ids;
}

bool Triangulation::FaceWithCorners(const std::array<uint32_t, 3>& ids,
                                    Face_handle* face) const {
  std::array<Vertex_handle, 3> corners;
  for (int i = 0; i < 3; ++i) {
    if (ids[i] >= by_input_.size()) return false;
    corners[i] = by_input_[ids[i]];
    if (corners[i]->info().id != ids[i]) return false;  // merged
  }
  // The face is among those around its first corner.
  auto f = dt_.incident_faces(corners[0]);
  const auto end = f;
  do {
    const int i = f->index(corners[0]);
    if (!dt_.is_infinite(f) && f->vertex(Ccw(i)) == corners[1] &&
        f->vertex(Cw(i)) == corners[2]) {
      *face = f;
      return true;
    }
  } while (++f != end);
  return false;
}

LocateResult Triangulation::ReferenceLocate(const Point2& q) const {
  Cdt::Locate_type lt;
  int li = -1;
  Face_handle f = dt_.locate(ToCgal(q), lt, li);
  LocationType type = LocationType::kOutsideConvexHull;
  switch (lt) {
    case Cdt::FACE:
      type = LocationType::kFace;
      break;
    case Cdt::EDGE:
      type = LocationType::kEdge;
      if (dt_.is_infinite(f)) {
        const int mirror = dt_.mirror_index(f, li);
        f = f->neighbor(li);
        li = mirror;
      }
      break;
    case Cdt::VERTEX: {
      type = LocationType::kVertex;
      const Vertex_handle v = f->vertex(li);
      f = FiniteFaceAt(v);
      li = f->index(v);
      break;
    }
    default: {  // OUTSIDE_CONVEX_HULL; dimension 2 excludes the affine case.
      const int k = f->index(dt_.infinite_vertex());
      li = dt_.mirror_index(f, k);
      f = f->neighbor(k);
      break;
    }
  }
  // CGAL's face, described by the serving mesh (the same triangle there,
  // its corners rotated).
  uint32_t face = MeshFace(f);
  if (type != LocationType::kFace) li = MeshIndex(f, li);
  if (type == LocationType::kOutsideConvexHull) {
    mesh_->NearestVisibleHullEdge(&face, &li, q);
  }
  LocateResult r;
  mesh_->Describe(face, type, li, q, &r);
  return r;
}

bool Triangulation::Agrees(const Point2& q, const LocateResult& got,
                           const LocateResult& reference) const {
  if (got.type != reference.type) return false;
  const int fi = reference.feature_index;
  switch (reference.type) {
    case LocationType::kFace:
      return std::is_permutation(got.vertex_ids.begin(), got.vertex_ids.end(),
                                 reference.vertex_ids.begin());
    case LocationType::kEdge:
      return Contains(got.vertex_ids, reference.vertex_ids[Ccw(fi)]) &&
             Contains(got.vertex_ids, reference.vertex_ids[Cw(fi)]);
    case LocationType::kVertex:
      return Contains(got.vertex_ids, reference.vertex_ids[fi]);
    case LocationType::kOutsideDomain:
      return std::minmax(got.domain_edge_ids[0], got.domain_edge_ids[1]) ==
             std::minmax(reference.domain_edge_ids[0],
                         reference.domain_edge_ids[1]);
    case LocationType::kOutsideConvexHull:
      break;
  }
  const int64_t a = got.hull_edge_ids[0];
  const int64_t b = got.hull_edge_ids[1];
  Point2 pa, pb;
  if (!VertexPoint(a, &pa) || !VertexPoint(b, &pb)) return false;
  Face_handle f;
  int i = -1;
  if (!dt_.is_edge(by_input_[a], by_input_[b], f, i)) return false;
  const bool on_hull = dt_.is_infinite(f) || dt_.is_infinite(f->neighbor(i));
  return on_hull && CGAL::orientation(ToCgal(pa), ToCgal(pb), ToCgal(q)) ==
                        CGAL::RIGHT_TURN;
}

}  // namespace locator
