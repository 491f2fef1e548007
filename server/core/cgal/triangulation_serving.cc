// Triangulation::Builder's last step: the serving mesh (serving_mesh.h),
// derived from the finished CGAL triangulation, and the triangle ids, which
// are the mesh's triangle indices.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/hilbert.h"
#include "common/status_macros.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/cgal/triangulation_builder.h"
#include "server/core/tiling/build_checks.h"
#include "server/core/tiling/mesh_vectors.h"

namespace locator {

Status Triangulation::Builder::BuildServingMesh() {
  const size_t vertex_count = dt_.number_of_vertices();
  const size_t face_count = dt_.number_of_faces();
  RETURN_IF_ERROR(CheckMeshSize(vertex_count, face_count));
  const BoundingBox& box = t_.box_;
  auto storage = std::make_unique<MeshVectors>();

  // Vertices in Hilbert order of their points (ties by id).
  std::vector<std::pair<uint32_t, Vertex_handle>> vertices;
  vertices.reserve(vertex_count);
  for (auto v = dt_.finite_vertices_begin(); v != dt_.finite_vertices_end();
       ++v) {
    vertices.emplace_back(HilbertKey(FromCgal(v->point()), box), v);
  }
  std::sort(vertices.begin(), vertices.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first, a.second->info().id) <
           std::tie(b.first, b.second->info().id);
  });
  std::vector<uint32_t> mesh_vertex(t_.by_input_.size());
  storage->points.reserve(vertex_count);
  storage->ids.reserve(vertex_count);
  if (t_.has_values_) storage->values.reserve(vertex_count);
  for (const auto& [key, v] : vertices) {
    mesh_vertex[v->info().id] = static_cast<uint32_t>(storage->points.size());
    storage->points.push_back(FromCgal(v->point()));
    storage->ids.push_back(static_cast<uint32_t>(v->info().id));
    if (t_.has_values_) storage->values.push_back(v->info().value);
  }
  std::vector<std::pair<uint32_t, Vertex_handle>>().swap(vertices);

  // Faces: in-domain first, each group in Hilbert order of centroids (ties
  // by corner ids), each face's corners rotated so that corner 0 has the
  // smallest id: the order and corners depend only on the triangulation,
  // and are the tiled build's (tiling/mesh_assembly.h).
  struct FaceKey {
    bool out;
    uint32_t key;
    std::array<uint32_t, 3> ids;  // rotated
    Face_handle face;
    int rotation;  // mesh corner j is CGAL's vertex (j + rotation) % 3
  };
  std::vector<FaceKey> faces;
  faces.reserve(face_count);
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    const std::array<uint32_t, 3> cgal_ids = t_.CornerIds(f);
    const int r = static_cast<int>(
        std::min_element(cgal_ids.begin(), cgal_ids.end()) - cgal_ids.begin());
    const auto corner = [&](int j) { return f->vertex((j + r) % 3); };
    const uint32_t key = ServingMesh::CentroidKey(
        FromCgal(corner(0)->point()), FromCgal(corner(1)->point()),
        FromCgal(corner(2)->point()), box);
    faces.push_back(
        FaceKey{!t_.InDomain(f),
                key,
                {cgal_ids[r], cgal_ids[(r + 1) % 3], cgal_ids[(r + 2) % 3]},
                f,
                r});
  }
  std::sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) {
    return std::tie(a.out, a.key, a.ids) < std::tie(b.out, b.key, b.ids);
  });
  // Face info becomes the mesh index (for now also outside the domain).
  for (size_t k = 0; k < faces.size(); ++k) {
    faces[k].face->info() = static_cast<int64_t>(k);
  }
  storage->triangles.resize(faces.size());
  for (size_t k = 0; k < faces.size(); ++k) {
    const Face_handle f = faces[k].face;
    MeshTriangle& m = storage->triangles[k];
    for (int j = 0; j < 3; ++j) {
      const int i = (j + faces[k].rotation) % 3;  // edge j is CGAL's edge i
      m.corner[j] = mesh_vertex[f->vertex(i)->info().id];
      if (f->is_constrained(i)) m.corner[j] |= ServingMesh::kConstrainedBit;
      const Face_handle n = f->neighbor(i);
      m.neighbor[j] = dt_.is_infinite(n) ? ServingMesh::kHullBit
                                         : static_cast<uint32_t>(n->info());
    }
  }
  // The hull, around the infinite vertex (each edge ends where the one
  // before it starts), from the edge ending at the smallest id.
  auto fc = dt_.incident_faces(dt_.infinite_vertex());
  const auto end = fc;
  do {
    const int k = fc->index(dt_.infinite_vertex());
    const Face_handle f = fc->neighbor(k);
    const auto face = static_cast<uint32_t>(f->info());
    const int j = (dt_.mirror_index(fc, k) + 3 - faces[face].rotation) % 3;
    storage->hull.push_back(ServingMesh::Edge(face, j));
  } while (++fc != end);
  const auto end_id = [&](uint32_t edge) {
    return faces[ServingMesh::EdgeFace(edge)]
        .ids[Cw(ServingMesh::EdgeIndex(edge))];
  };
  std::rotate(storage->hull.begin(),
              std::min_element(storage->hull.begin(), storage->hull.end(),
                               [&](uint32_t a, uint32_t b) {
                                 return end_id(a) < end_id(b);
                               }),
              storage->hull.end());
  for (size_t k = 0; k < storage->hull.size(); ++k) {
    const uint32_t edge = storage->hull[k];
    storage->triangles[ServingMesh::EdgeFace(edge)]
        .neighbor[ServingMesh::EdgeIndex(edge)] =
        ServingMesh::kHullBit | static_cast<uint32_t>(k);
  }
  // Face info: the mesh index k in the domain, -2 - k outside it.
  for (const FaceKey& f : faces) {
    if (f.out) f.face->info() = -2 - f.face->info();
  }

  ServingMesh::Arrays arrays = storage->Views();
  arrays.in_domain = static_cast<uint32_t>(t_.num_triangles_);
  arrays.box = box;
  arrays.input_points = t_.input_points_;
  arrays.digest = t_.VertexDigest();
  t_.mesh_ = std::make_shared<const ServingMesh>(std::move(storage), arrays);
  return Status::OK();
}

}  // namespace locator
