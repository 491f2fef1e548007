#include "server/core/terrain/grid/grid_output.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "common/status_macros.h"
#include "server/core/cgal/orientation.h"
#include "server/core/mesh/large_vector.h"
#include "server/core/mesh/radix_sort.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/terrain/grid/grid_error.h"

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

void SortRowMajor(TinMesh* mesh) {
  // Vertices by column, then (stably) by row: by sample index.
  const auto n = static_cast<uint32_t>(mesh->num_vertices());
  LargeVector<uint64_t> items(n);
  for (uint32_t v = 0; v < n; ++v) {
    items[v] = (static_cast<uint64_t>(mesh->point(v).x) << 32) | v;
  }
  SortByHighHalf(&items);
  for (uint64_t& item : items) {
    const auto v = static_cast<uint32_t>(item);
    item = (static_cast<uint64_t>(mesh->point(v).y) << 32) | v;
  }
  SortByHighHalf(&items);
  std::vector<uint32_t> vertices(n);
  std::vector<uint32_t> rank(n);
  for (uint32_t k = 0; k < n; ++k) {
    vertices[k] = static_cast<uint32_t>(items[k]);
    rank[vertices[k]] = k;
  }
  // Triangles by their first corner in that order, then by index.
  items.resize(mesh->num_triangles());
  for (uint32_t t = 0; t < items.size(); ++t) {
    const uint32_t first =
        std::min({rank[mesh->Corner(t, 0)], rank[mesh->Corner(t, 1)],
                  rank[mesh->Corner(t, 2)]});
    items[t] = (uint64_t{first} << 32) | t;
  }
  std::vector<uint32_t>().swap(rank);
  SortByHighHalf(&items);
  std::vector<uint32_t> triangles(items.size());
  for (size_t k = 0; k < items.size(); ++k) {
    triangles[k] = static_cast<uint32_t>(items[k]);
  }
  LargeVector<uint64_t>().swap(items);
  mesh->Renumber(vertices, triangles);
}

Status WriteGridTin(const ElevationGrid& grid, const TinMesh& mesh,
                    Dataset* out) {
  RETURN_IF_ERROR(CheckSize(mesh.num_vertices(), mesh.num_triangles()));
  StartOutput(grid, out);
  out->points.reserve(mesh.num_vertices());
  out->values.reserve(mesh.num_vertices());
  for (uint32_t v = 0; v < mesh.num_vertices(); ++v) {
    const Point2& p = mesh.point(v);
    const auto col = static_cast<uint32_t>(p.x);
    const auto row = static_cast<uint32_t>(p.y);
    out->points.push_back(grid.SampleAt(col, row));
    out->values.push_back(grid.ValueAt(col, row));
  }
  const bool mirrors = OutputMirrors(grid);
  out->constraints.triangles.reserve(mesh.num_triangles());
  for (uint32_t t = 0; t < mesh.num_triangles(); ++t) {
    RETURN_IF_ERROR(AddTriangle(grid, mirrors, mesh.Corner(t, 0),
                                mesh.Corner(t, 1), mesh.Corner(t, 2), out));
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
      RETURN_IF_ERROR(
          CheckSize(out->points.size(), out->constraints.triangles.size() + 2));
      Status s = AddTriangle(grid, mirrors, a, b, d, out);
      if (s.ok()) s = AddTriangle(grid, mirrors, a, d, c, out);
      if (!s.ok()) return s;
    }
    std::swap(above, row_ids);
  }
  return Status::OK();
}

}  // namespace locator
