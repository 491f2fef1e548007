// Engine::MeshInBox: the TIN's triangles over a box, as a MeshPatch.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "locator/engine.h"
#include "server/core/mesh/serving_mesh.h"

namespace locator {

Status Engine::MeshInBox(const BoundingBox& box, size_t max_vertices,
                         MeshPatch* out) const {
  *out = MeshPatch();
  const ServingMesh& mesh = *mesh_;
  if (!mesh.has_values()) {
    return Status::FailedPrecondition("the dataset has no values");
  }
  if (!std::isfinite(box.min_x) || !std::isfinite(box.min_y) ||
      !std::isfinite(box.max_x) || !std::isfinite(box.max_y)) {
    return Status::InvalidArgument("the box of a mesh patch must be finite");
  }
  // One pass over the in-domain triangles: a tile's box is cut out once
  // per request, and a scan of the flat array costs less than the
  // transforms of the vertices it finds.
  constexpr uint32_t kUnused = 0xffffffffu;
  std::vector<uint32_t> index_of;
  for (uint32_t f = 0; f < mesh.num_triangles(); ++f) {
    const Point2& a = mesh.CornerPoint(f, 0);
    const Point2& b = mesh.CornerPoint(f, 1);
    const Point2& c = mesh.CornerPoint(f, 2);
    if (std::max({a.x, b.x, c.x}) < box.min_x ||
        std::min({a.x, b.x, c.x}) > box.max_x ||
        std::max({a.y, b.y, c.y}) < box.min_y ||
        std::min({a.y, b.y, c.y}) > box.max_y) {
      continue;
    }
    if (index_of.empty()) index_of.assign(mesh.num_vertices(), kUnused);
    std::array<uint32_t, 3> triangle;
    for (int i = 0; i < 3; ++i) {
      const uint32_t v = mesh.Corner(f, i);
      if (index_of[v] == kUnused) {
        if (out->size() == max_vertices) {
          *out = MeshPatch();
          return Status::ResourceExhausted(
              "the triangles over the box have more than " +
              std::to_string(max_vertices) + " vertices");
        }
        index_of[v] = static_cast<uint32_t>(out->size());
        out->points.push_back(mesh.arrays().points[v]);
        out->heights.push_back(mesh.arrays().values[v]);
        out->keys.push_back(static_cast<uint32_t>(mesh.PublicId(v)));
      }
      triangle[i] = index_of[v];
    }
    out->triangles.push_back(triangle);
  }
  return Status::OK();
}

}  // namespace locator
