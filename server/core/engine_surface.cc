// Engine's surface queries: interpolation, profiles and rasters.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "common/status_macros.h"
#include "locator/engine.h"
#include "server/core/mesh/serving_mesh.h"
#include "server/core/strategies/point_locator.h"
#include "server/core/surface/profile_trace.h"
#include "server/core/surface/raster_render.h"
#include "server/core/surface/surface_value.h"

namespace locator {
namespace {

// A face near q, found the way the strategy starts a locate of q: the
// triangle of its answer, or outside the domain and the hull, the triangle
// next to q along the mesh's Hilbert order.
uint32_t StartNear(const ServingMesh& mesh, const PointLocator& locator,
                   const Point2& q) {
  LocateResult r;
  locator.Locate(q, &r);
  return r.triangle_id >= 0 ? static_cast<uint32_t>(r.triangle_id)
                            : mesh.TriangleNear(q);
}

// The face a scan of `points` starts at: near the first finite point;
// nullopt if none is finite.
std::optional<uint32_t> ScanStart(const ServingMesh& mesh,
                                  const PointLocator& locator,
                                  std::span<const Point2> points) {
  const auto first = std::find_if(points.begin(), points.end(),
                                  [](const Point2& p) { return IsFinite(p); });
  if (first == points.end()) return std::nullopt;
  return StartNear(mesh, locator, *first);
}

}  // namespace

Status Engine::CheckInterpolation(Interpolation how) const {
  return ::locator::CheckInterpolation(info_.constraints, how);
}

Detail Engine::StrategyDetail(Interpolation how, Detail detail) {
  return how == Interpolation::kLinear || detail != Detail::kFull
             ? detail
             : Detail::kAllButValue;
}

void Engine::InterpolateValues(std::span<const Point2> queries,
                               Interpolation how, LocateResult* results) const {
  for (size_t i = 0; i < queries.size(); ++i) {
    LocateResult& r = results[i];
    // A value means an in-domain triangle, whose id is its mesh index.
    if (!r.has_value) continue;
    r.value =
        ValueAt(*mesh_, static_cast<uint32_t>(r.triangle_id), queries[i], how);
  }
}

Status Engine::TraceProfile(std::span<const Point2> line,
                            const ProfileOptions& options, Profile* out) const {
  RETURN_IF_ERROR(CheckInterpolation(options.interpolation));
  const ServingMesh& mesh = *mesh_;
  // The trace checks the line itself; the strategy only sees a good point.
  const uint32_t start = !line.empty() && IsFinite(line[0])
                             ? StartNear(mesh, *locator_, line[0])
                             : mesh.DefaultStart();
  return ::locator::TraceProfile(mesh, start, line, options, out);
}

Status Engine::RenderRows(const RasterSpec& spec, uint32_t first_row,
                          uint32_t rows, double* out) const {
  RETURN_IF_ERROR(CheckRasterSpec(spec));
  RETURN_IF_ERROR(CheckInterpolation(spec.interpolation));
  if (first_row > spec.height || rows > spec.height - first_row) {
    return Status::InvalidArgument(
        "rows " + std::to_string(first_row) + ".." +
        std::to_string(uint64_t{first_row} + rows) + " are not within the " +
        std::to_string(spec.height) + " rows of the raster");
  }
  if (rows == 0) return Status::OK();
  const ServingMesh& mesh = *mesh_;
  ::locator::RenderRows(
      mesh, StartNear(mesh, *locator_, spec.CellCentre(0, first_row)), spec,
      first_row, rows, out);
  return Status::OK();
}

Status Engine::RenderPoints(std::span<const Point2> points, size_t row_length,
                            Interpolation how, double nodata,
                            double* out) const {
  if (Status s = CheckInterpolation(how); !s.ok()) return s;
  if (row_length == 0) {
    return Status::InvalidArgument("RenderPoints: row_length must be >= 1");
  }
  const std::optional<uint32_t> start = ScanStart(*mesh_, *locator_, points);
  if (!start.has_value()) {
    std::fill_n(out, points.size(), nodata);
    return Status::OK();
  }
  ::locator::RenderPoints(*mesh_, *start, points, row_length, how, nodata, out);
  return Status::OK();
}

Status Engine::RenderGradients(std::span<const Point2> points,
                               size_t row_length, FacetGradient* out) const {
  if (row_length == 0) {
    return Status::InvalidArgument("RenderGradients: row_length must be >= 1");
  }
  const std::optional<uint32_t> start = ScanStart(*mesh_, *locator_, points);
  if (!start.has_value()) {
    std::fill_n(out, points.size(), FacetGradient{});
    return Status::OK();
  }
  ::locator::RenderGradients(*mesh_, *start, points, row_length, out);
  return Status::OK();
}

}  // namespace locator
