#include "server/core/terrain/grid_output.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "server/core/orientation.h"
#include "server/core/serving_mesh.h"
#include "server/core/terrain/grid_error.h"

namespace locator {

namespace {

constexpr uint32_t kNoVertex = 0xffffffffu;

Status CheckSize(uint64_t vertices, uint64_t triangles) {
  if (vertices <= ServingMesh::kMaxElements &&
      triangles <= ServingMesh::kMaxElements) {
    return Status::OK();
  }
  return Status::InvalidArgument(
      "the TIN has " + std::to_string(vertices) + " vertices and " +
      std::to_string(triangles) + " triangles; a serving mesh holds at most " +
      std::to_string(ServingMesh::kMaxElements) +
      " of each (raise max_error or set max_points)");
}

// Appends triangle (a, b, c), counter-clockwise in grid coordinates, to
// out's triangles counter-clockwise in dataset coordinates; InvalidArgument
// if it is not strictly so there.
Status AddTriangle(const ElevationGrid& grid, bool mirrors, uint32_t a,
                   uint32_t b, uint32_t c, Dataset* out) {
  const std::array<uint32_t, 3> corners =
      mirrors ? std::array<uint32_t, 3>{a, c, b}
              : std::array<uint32_t, 3>{a, b, c};
  const std::vector<Point2>& p = out->points;
  if (Orientation(p[corners[0]], p[corners[1]], p[corners[2]]) != Side::kLeft) {
    return Status::InvalidArgument(
        "placing the samples in dataset coordinates (origin " +
        std::to_string(grid.origin_x) + ", " + std::to_string(grid.origin_y) +
        ", step " + std::to_string(grid.step_x) + ", " +
        std::to_string(grid.step_y) +
        ") rounds a triangle flat: the step is too small for the origin");
  }
  out->constraints.triangles.push_back(corners);
  return Status::OK();
}

void StartOutput(const ElevationGrid& grid, Dataset* out) {
  *out = Dataset();
  out->crs = grid.crs;
  out->source = grid.source;
}

}  // namespace

Status WriteGridTin(const ElevationGrid& grid, const TinMesh& mesh,
                    Dataset* out) {
  if (Status s = CheckSize(mesh.num_vertices(), mesh.num_triangles());
      !s.ok()) {
    return s;
  }
  StartOutput(grid, out);
  // Vertices in row-major order of their samples.
  std::vector<std::pair<uint64_t, uint32_t>> order(mesh.num_vertices());
  for (uint32_t v = 0; v < mesh.num_vertices(); ++v) {
    const Point2& p = mesh.point(v);
    order[v] = {
        static_cast<uint64_t>(p.y) * grid.width + static_cast<uint64_t>(p.x),
        v};
  }
  std::sort(order.begin(), order.end());
  std::vector<uint32_t> id(mesh.num_vertices());
  out->points.reserve(order.size());
  out->values.reserve(order.size());
  for (const auto& [sample, v] : order) {
    id[v] = static_cast<uint32_t>(out->points.size());
    const auto col = static_cast<uint32_t>(sample % grid.width);
    const auto row = static_cast<uint32_t>(sample / grid.width);
    out->points.push_back(grid.SampleAt(col, row));
    out->values.push_back(grid.ValueAt(col, row));
  }
  std::vector<std::pair<uint64_t, uint32_t>>().swap(order);
  const bool mirrors = OutputMirrors(grid);
  out->constraints.triangles.reserve(mesh.num_triangles());
  for (uint32_t t = 0; t < mesh.num_triangles(); ++t) {
    if (Status s =
            AddTriangle(grid, mirrors, id[mesh.Corner(t, 0)],
                        id[mesh.Corner(t, 1)], id[mesh.Corner(t, 2)], out);
        !s.ok()) {
      return s;
    }
  }
  return Status::OK();
}

Status WriteGridCells(const ElevationGrid& grid, const CellMask& mask,
                      Dataset* out) {
  StartOutput(grid, out);
  const bool mirrors = OutputMirrors(grid);
  // The ids of the domain's samples in the previous and the current row.
  std::vector<uint32_t> above(grid.width, kNoVertex);
  std::vector<uint32_t> row_ids(grid.width, kNoVertex);
  for (uint32_t row = 0; row < grid.height; ++row) {
    for (uint32_t col = 0; col < grid.width; ++col) {
      const bool in_domain = mask.Valid(col - int64_t{1}, row - int64_t{1}) ||
                             mask.Valid(col, row - int64_t{1}) ||
                             mask.Valid(col - int64_t{1}, row) ||
                             mask.Valid(col, row);
      row_ids[col] = kNoVertex;
      if (!in_domain) continue;
      if (out->points.size() >= ServingMesh::kMaxElements) {
        return CheckSize(grid.samples(), 2 * mask.valid_cells());
      }
      row_ids[col] = static_cast<uint32_t>(out->points.size());
      out->points.push_back(grid.SampleAt(col, row));
      out->values.push_back(grid.ValueAt(col, row));
    }
    for (uint32_t col = 0; row > 0 && col + 1 < grid.width; ++col) {
      if (!mask.Valid(col, row - int64_t{1})) continue;
      const uint32_t a = above[col], b = above[col + 1];
      const uint32_t c = row_ids[col], d = row_ids[col + 1];
      if (Status s = CheckSize(out->points.size(),
                               out->constraints.triangles.size() + 2);
          !s.ok()) {
        return s;
      }
      Status s = AddTriangle(grid, mirrors, a, b, d, out);
      if (s.ok()) s = AddTriangle(grid, mirrors, a, d, c, out);
      if (!s.ok()) return s;
    }
    std::swap(above, row_ids);
  }
  return Status::OK();
}

}  // namespace locator
