// BuildGivenMesh (given_mesh.h) and GivenMeshBuilder::Serve: the serving
// mesh of a checked mesh, in BuildServingMesh's order.

#include "server/core/cgal/given_mesh.h"

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/hilbert.h"
#include "common/status_macros.h"
#include "server/core/cgal/domain_outline.h"
#include "server/core/cgal/given_mesh_builder.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

bool IsGivenMesh(const Dataset& dataset) {
  const DatasetConstraints& c = dataset.constraints;
  return !c.triangles.empty() && c.breaklines.empty() && c.rings.empty() &&
         c.segments.empty() && c.hole_seeds.empty();
}

StatusOr<BuiltMesh> BuildGivenMesh(const Dataset& dataset) {
  GivenMeshBuilder builder(dataset);
  RETURN_IF_ERROR(builder.Check());
  return builder.Serve();
}

StatusOr<BuiltMesh> GivenMeshBuilder::Serve() {
  const std::vector<Point2>& pts = d_.points;
  const size_t face_count = tri_.size() + [&] {
    size_t outside = 0;
    for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end();
         ++f) {
      outside += f->info().side == Side::kOutside;
    }
    return outside;
  }();
  if (face_count > ServingMesh::kMaxElements) {
    return Status::InvalidArgument(
        "the triangulation has " + std::to_string(face_count) +
        " triangles; the serving mesh holds at most " +
        std::to_string(ServingMesh::kMaxElements));
  }
  BoundingBox box;
  for (const Point2& p : pts) box.Extend(p);
  auto storage = std::make_unique<ServingMesh::VectorStorage>();

  // Vertices in Hilbert order of their points, ties by id.
  std::vector<std::pair<uint32_t, uint32_t>> vertices;
  for (uint32_t id = 0; id < pts.size(); ++id) {
    if (first_[id] == id) vertices.emplace_back(HilbertKey(pts[id], box), id);
  }
  std::sort(vertices.begin(), vertices.end());
  std::vector<uint32_t> mesh_vertex(pts.size(), kNone);
  for (const auto& [key, id] : vertices) {
    mesh_vertex[id] = static_cast<uint32_t>(storage->points.size());
    storage->points.push_back(pts[id]);
    storage->ids.push_back(id);
    if (!d_.values.empty()) storage->values.push_back(d_.values[id]);
  }
  decltype(vertices)().swap(vertices);

  // Faces: the given triangles (in the domain) first, then the outside
  // faces, each group in Hilbert order of centroids, ties by corner ids.
  struct FaceKey {
    bool out;
    uint32_t key;
    std::array<uint32_t, 3> ids;
    uint32_t given;  // the triangle, or kNone
    Face_handle face;
  };
  std::vector<FaceKey> faces;
  faces.reserve(face_count);
  for (uint32_t k = 0; k < tri_.size(); ++k) {
    const std::array<uint32_t, 3>& t = tri_[k];
    faces.push_back(FaceKey{
        false, ServingMesh::CentroidKey(pts[t[0]], pts[t[1]], pts[t[2]], box),
        t, k, Face_handle()});
  }
  for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
    if (f->info().side != Side::kOutside) continue;
    const std::array<uint32_t, 3> ids = {f->vertex(0)->info().id,
                                         f->vertex(1)->info().id,
                                         f->vertex(2)->info().id};
    faces.push_back(FaceKey{
        true,
        ServingMesh::CentroidKey(pts[ids[0]], pts[ids[1]], pts[ids[2]], box),
        ids, kNone, f});
  }
  std::sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) {
    return std::tie(a.out, a.key, a.ids) < std::tie(b.out, b.key, b.ids);
  });
  std::vector<uint32_t> given_index(tri_.size());
  for (uint32_t k = 0; k < faces.size(); ++k) {
    if (faces[k].given != kNone) {
      given_index[faces[k].given] = k;
    } else {
      faces[k].face->info().index = k;
    }
  }
  // The given half-edge on the inside of the edge from p to q.
  const auto inside_edge = [&](uint32_t p, uint32_t q) {
    const uint32_t h = boundary_.at(Key(p, q));
    return ServingMesh::Edge(given_index[h / 3], static_cast<int>(h % 3));
  };
  storage->triangles.resize(faces.size());
  for (size_t k = 0; k < faces.size(); ++k) {
    MeshTriangle& m = storage->triangles[k];
    const FaceKey& face = faces[k];
    for (int i = 0; i < 3; ++i) {
      m.corner[i] = mesh_vertex[face.ids[i]];
      if (face.given != kNone) {
        // Every edge of a given mesh is constrained.
        m.corner[i] |= ServingMesh::kConstrainedBit;
        const uint32_t twin = twin_[3 * face.given + i];
        m.neighbor[i] = twin != kNone ? given_index[twin / 3] : kNone;
        continue;
      }
      const Face_handle f = face.face;
      if (f->is_constrained(i)) m.corner[i] |= ServingMesh::kConstrainedBit;
      const Face_handle n = f->neighbor(i);
      if (cdt_.is_infinite(n)) {
        m.neighbor[i] = ServingMesh::kHullBit;  // set with the hull below
      } else if (n->info().side == Side::kOutside) {
        m.neighbor[i] = n->info().index;
      } else {
        // f lies left of its edge from ccw(i) to cw(i); the triangle
        // inside runs it the other way.
        const uint32_t edge = inside_edge(f->vertex(cdt_.cw(i))->info().id,
                                          f->vertex(cdt_.ccw(i))->info().id);
        m.neighbor[i] = ServingMesh::EdgeFace(edge);
        storage->triangles[ServingMesh::EdgeFace(edge)]
            .neighbor[ServingMesh::EdgeIndex(edge)] = static_cast<uint32_t>(k);
      }
    }
  }
  // The hull, around the infinite vertex.
  auto fc = cdt_.incident_faces(cdt_.infinite_vertex());
  const auto end = fc;
  do {
    const int k = fc->index(cdt_.infinite_vertex());
    const Face_handle f = fc->neighbor(k);
    const int i = cdt_.mirror_index(fc, k);
    const uint32_t edge = f->info().side == Side::kOutside
                              ? ServingMesh::Edge(f->info().index, i)
                              : inside_edge(f->vertex(cdt_.ccw(i))->info().id,
                                            f->vertex(cdt_.cw(i))->info().id);
    storage->triangles[ServingMesh::EdgeFace(edge)]
        .neighbor[ServingMesh::EdgeIndex(edge)] =
        ServingMesh::kHullBit | static_cast<uint32_t>(storage->hull.size());
    storage->hull.push_back(edge);
  } while (++fc != end);

  // Triangulation::VertexDigest over the same triangulation: the distinct
  // points by id, then the constrained edges (all the mesh's) and the
  // in-domain triangles, by sorted ids.
  Xxh3Digest hash;
  for (uint32_t id = 0; id < pts.size(); ++id) {
    if (first_[id] != id) continue;
    hash.AddU64(id);
    hash.AddDouble(pts[id].x);
    hash.AddDouble(pts[id].y);
  }
  std::vector<std::array<int64_t, 3>> items;
  for (uint32_t h = 0; h < twin_.size(); ++h) {
    if (twin_[h] != kNone && twin_[h] < h) continue;  // counted from its twin
    const auto [a, b] = std::minmax({From(h), To(h)});
    items.push_back({-1, a, b});
  }
  for (const std::array<uint32_t, 3>& t : tri_) {
    std::array<int64_t, 3> ids = {t[0], t[1], t[2]};
    std::sort(ids.begin(), ids.end());
    items.push_back(ids);
  }
  std::sort(items.begin(), items.end());
  for (const auto& item : items) {
    for (const int64_t id : item) hash.AddU64(static_cast<uint64_t>(id));
  }

  // Holes: regions of outside faces that do not reach the hull.
  uint64_t holes = 0;
  std::vector<bool> seen(faces.size());
  std::vector<uint32_t> region;
  for (uint32_t k = static_cast<uint32_t>(tri_.size()); k < faces.size(); ++k) {
    if (seen[k]) continue;
    bool hull = false;
    region.assign(1, k);
    seen[k] = true;
    while (!region.empty()) {
      const MeshTriangle& m = storage->triangles[region.back()];
      region.pop_back();
      for (const uint32_t n : m.neighbor) {
        if (ServingMesh::IsHull(n)) {
          hull = true;
        } else if (n >= tri_.size() && !seen[n]) {
          seen[n] = true;
          region.push_back(n);
        }
      }
    }
    holes += hull ? 0 : 1;
  }

  ServingMesh::Arrays arrays;
  arrays.triangles = storage->triangles;
  arrays.points = storage->points;
  arrays.values = storage->values;
  arrays.ids = storage->ids;
  arrays.hull = storage->hull;
  arrays.in_domain = static_cast<uint32_t>(tri_.size());
  arrays.box = box;
  arrays.input_points = pts.size();
  arrays.digest = hash.digest();
  BuiltMesh built;
  built.mesh = std::make_shared<const ServingMesh>(std::move(storage), arrays);
  built.facts.constraints = mesh_edges_;
  built.facts.holes = holes;
  built.facts.duplicates_merged = pts.size() - distinct_;
  built.facts.outline = OutlineOfMesh(*built.mesh, kOutlineSize);
  built.facts.edge_sample = built.mesh->SampleEdges(kEdgeSampleSize);
  return built;
}

}  // namespace locator
