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

#include "server/core/hilbert.h"
#include "server/core/triangulation.h"
#include "server/core/triangulation_builder.h"

namespace locator {

Status Triangulation::Builder::BuildServingMesh() {
  const size_t vertex_count = dt_.number_of_vertices();
  const size_t face_count = dt_.number_of_faces();
  if (vertex_count > ServingMesh::kMaxElements ||
      face_count > ServingMesh::kMaxElements) {
    return Status::InvalidArgument(
        "the triangulation has " + std::to_string(face_count) +
        " triangles; the serving mesh holds at most " +
        std::to_string(ServingMesh::kMaxElements));
  }
  const BoundingBox& box = t_.box_;
  auto storage = std::make_unique<ServingMesh::VectorStorage>();

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
  // by corner ids, so the order depends only on the triangulation).
  struct FaceKey {
    bool out;
    uint32_t key;
    std::array<uint32_t, 3> ids;
    Face_handle face;
  };
  std::vector<FaceKey> faces;
  faces.reserve(face_count);
  for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f) {
    const uint32_t key = ServingMesh::CentroidKey(
        FromCgal(f->vertex(0)->point()), FromCgal(f->vertex(1)->point()),
        FromCgal(f->vertex(2)->point()), box);
    faces.push_back(FaceKey{!t_.InDomain(f), key, t_.CornerIds(f), f});
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
    for (int i = 0; i < 3; ++i) {
      m.corner[i] = mesh_vertex[f->vertex(i)->info().id];
      if (f->is_constrained(i)) m.corner[i] |= ServingMesh::kConstrainedBit;
      const Face_handle n = f->neighbor(i);
      m.neighbor[i] = dt_.is_infinite(n) ? ServingMesh::kHullBit
                                         : static_cast<uint32_t>(n->info());
    }
  }
  // The hull, around the infinite vertex.
  auto fc = dt_.incident_faces(dt_.infinite_vertex());
  const auto end = fc;
  do {
    const int k = fc->index(dt_.infinite_vertex());
    const Face_handle f = fc->neighbor(k);
    const int i = dt_.mirror_index(fc, k);
    const auto face = static_cast<uint32_t>(f->info());
    storage->triangles[face].neighbor[i] =
        ServingMesh::kHullBit | static_cast<uint32_t>(storage->hull.size());
    storage->hull.push_back(ServingMesh::Edge(face, i));
  } while (++fc != end);
  // Face info: the mesh index k in the domain, -2 - k outside it.
  for (const FaceKey& f : faces) {
    if (f.out) f.face->info() = -2 - f.face->info();
  }

  ServingMesh::Arrays arrays;
  arrays.triangles = storage->triangles;
  arrays.points = storage->points;
  arrays.values = storage->values;
  arrays.ids = storage->ids;
  arrays.hull = storage->hull;
  arrays.in_domain = static_cast<uint32_t>(t_.num_triangles_);
  arrays.box = box;
  arrays.input_points = t_.input_points_;
  arrays.digest = t_.VertexDigest();
  t_.mesh_ = std::make_shared<const ServingMesh>(std::move(storage), arrays);
  return Status::OK();
}

}  // namespace locator
