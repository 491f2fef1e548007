// Engine's surface queries: interpolation, profiles and rasters.

#include <array>
#include <cstdint>
#include <string>

#include "server/core/engine.h"
#include "server/core/profile_trace.h"
#include "server/core/raster_render.h"
#include "server/core/surface_value.h"
#include "server/core/triangulation.h"

namespace locator {
namespace {

using Face_handle = Triangulation::Face_handle;

// The face of `r`'s triangle (the hull triangle outside the hull); for an
// answer outside the domain, a face at its nearest boundary edge.
Face_handle FaceOf(const Triangulation& t, const LocateResult& r) {
  const std::array<int64_t, 3>& ids = r.vertex_ids;
  Face_handle face;
  if (ids[0] >= 0 && t.FaceWithCorners({static_cast<uint32_t>(ids[0]),
                                        static_cast<uint32_t>(ids[1]),
                                        static_cast<uint32_t>(ids[2])},
                                       &face)) {
    return face;
  }
  if (r.domain_edge_ids[0] >= 0) {
    return t.FiniteFaceAt(
        t.VertexOfInput(static_cast<size_t>(r.domain_edge_ids[0])));
  }
  return t.DefaultStart();
}

// A finite face near q, found the way the strategy starts a locate of q.
Face_handle StartNear(const Triangulation& t, const PointLocator& locator,
                      const Point2& q) {
  LocateResult r;
  locator.Locate(q, &r);
  return FaceOf(t, r);
}

}  // namespace

Status Engine::CheckInterpolation(Interpolation how) const {
  return ::locator::CheckInterpolation(*triangulation_, how);
}

void Engine::Reinterpolate(std::span<const Point2> queries, Interpolation how,
                           LocateResult* results) const {
  if (how == Interpolation::kLinear) return;
  for (size_t i = 0; i < queries.size(); ++i) {
    LocateResult& r = results[i];
    if (!r.has_value) continue;
    r.value =
        ValueAt(*triangulation_, FaceOf(*triangulation_, r), queries[i], how);
  }
}

Status Engine::TraceProfile(std::span<const Point2> line,
                            const ProfileOptions& options, Profile* out) const {
  if (Status s = CheckInterpolation(options.interpolation); !s.ok()) return s;
  const Triangulation& t = *triangulation_;
  // The trace checks the line itself; the strategy only sees a good point.
  const Face_handle start = !line.empty() && IsFinite(line[0])
                                ? StartNear(t, *locator_, line[0])
                                : t.DefaultStart();
  return ::locator::TraceProfile(t, start, line, options, out);
}

Status Engine::RenderRows(const RasterSpec& spec, uint32_t first_row,
                          uint32_t rows, double* out) const {
  if (Status s = CheckRasterSpec(spec); !s.ok()) return s;
  if (Status s = CheckInterpolation(spec.interpolation); !s.ok()) return s;
  if (first_row > spec.height || rows > spec.height - first_row) {
    return Status::InvalidArgument(
        "rows " + std::to_string(first_row) + ".." +
        std::to_string(uint64_t{first_row} + rows) + " are not within the " +
        std::to_string(spec.height) + " rows of the raster");
  }
  if (rows == 0) return Status::OK();
  const Triangulation& t = *triangulation_;
  ::locator::RenderRows(t,
                        StartNear(t, *locator_, spec.CellCentre(0, first_row)),
                        spec, first_row, rows, out);
  return Status::OK();
}

}  // namespace locator
