#include "server/core/surface/raster_render.h"

#include <cmath>
#include <limits>
#include <string>

#include "common/input_text.h"
#include "common/status_macros.h"
#include "server/core/geometry/wide_math.h"
#include "server/core/mesh/mesh_walk.h"
#include "server/core/surface/surface_value.h"

namespace locator {

Status CheckRasterBox(const BoundingBox& b) {
  if (!IsFinite(Point2{b.min_x, b.min_y}) ||
      !IsFinite(Point2{b.max_x, b.max_y})) {
    return Status::InvalidArgument("the raster's box must be finite");
  }
  if (!(b.min_x < b.max_x) || !(b.min_y < b.max_y)) {
    return Status::InvalidArgument(
        "the raster's box must have min_x < max_x and min_y < max_y");
  }
  return Status::OK();
}

double RasterSpec::cell_width() const {
  return Step(box.min_x, box.max_x, width);
}

double RasterSpec::cell_height() const {
  return Step(box.min_y, box.max_y, height);
}

Point2 RasterSpec::CellCentre(uint32_t col, uint32_t row) const {
  return Point2{GridLine(box.min_x, box.max_x, col + 0.5, width),
                GridLine(box.max_y, box.min_y, row + 0.5, height)};
}

Status CheckRasterSpec(const RasterSpec& spec) {
  const BoundingBox& b = spec.box;
  RETURN_IF_ERROR(CheckRasterBox(b));
  if (spec.width == 0 || spec.height == 0) {
    return Status::InvalidArgument("the raster needs width and height >= 1");
  }
  const double cell_width = spec.cell_width();
  const double cell_height = spec.cell_height();
  if (!(cell_width > 0) || !(cell_height > 0) || !std::isfinite(cell_width) ||
      !std::isfinite(cell_height)) {
    return Status::InvalidArgument(
        "the raster's cells are not representable: the box " +
        PointText({b.min_x, b.min_y}) + " - " + PointText({b.max_x, b.max_y}) +
        " over " + std::to_string(spec.width) + " x " +
        std::to_string(spec.height) + " cells makes cells of " +
        NumberText(cell_width) + " x " + NumberText(cell_height) +
        "; a cell's width and height must be positive doubles, at most " +
        NumberText(std::numeric_limits<double>::max()));
  }
  return Status::OK();
}

namespace {

// The value at the cell centre q that the walk `w` located, or nodata
// outside the hull or the domain (a centre on the domain's boundary edge or
// vertex takes the in-domain side).
double CellValue(const ServingMesh& mesh, Interpolation how, double nodata,
                 const MeshWalkOutcome& w, const Point2& q) {
  if (!mesh.has_values()) return nodata;
  const uint32_t f = ClosedDomainFace(mesh, w);
  if (f == ServingMesh::kNoFace) return nodata;
  return ValueAt(mesh, f, q, how);
}

// Walks to each of `points` in scan order (see RenderPoints) and writes
// `at(w, q)` for each point q the walk `w` reached, or `none` for a point
// that is not finite.
template <class T, class AtPoint>
void ScanPoints(const ServingMesh& mesh, uint32_t hint,
                std::span<const Point2> points, size_t row_length, T none,
                AtPoint at, T* out) {
  uint32_t row_start = hint;
  uint32_t face = hint;
  bool row_started = false;
  for (size_t i = 0; i < points.size(); ++i) {
    // A row's first point is next to the previous row's, not to that row's
    // last point a tile's width away.
    if (i % row_length == 0) {
      face = row_start;
      row_started = false;
    }
    const Point2& q = points[i];
    if (!IsFinite(q)) {
      *out++ = none;
      continue;
    }
    const MeshWalkOutcome w = Walk(mesh, face, q);
    face = w.face;
    if (!row_started) row_start = face;
    row_started = true;
    *out++ = at(w, q);
  }
}

// The gradient of the plane through face f's corners and their values,
// from the normal (corner 1 - corner 0) x (corner 2 - corner 0): its z is
// twice the face's signed area, never 0 for a face of the mesh.
FacetGradient GradientOf(const ServingMesh& mesh, uint32_t f) {
  const Point2& a = mesh.CornerPoint(f, 0);
  const Point2& b = mesh.CornerPoint(f, 1);
  const Point2& c = mesh.CornerPoint(f, 2);
  const std::span<const double> values = mesh.arrays().values;
  const double va = values[mesh.Corner(f, 0)];
  const double ux = b.x - a.x, uy = b.y - a.y,
               uz = values[mesh.Corner(f, 1)] - va;
  const double vx = c.x - a.x, vy = c.y - a.y,
               vz = values[mesh.Corner(f, 2)] - va;
  const double nx = uy * vz - uz * vy;
  const double ny = uz * vx - ux * vz;
  const double nz = ux * vy - uy * vx;
  return FacetGradient{-nx / nz, -ny / nz};
}

}  // namespace

void RenderRows(const ServingMesh& mesh, uint32_t hint, const RasterSpec& spec,
                uint32_t first_row, uint32_t rows, double* out) {
  uint32_t row_start = hint;
  for (uint32_t r = 0; r < rows; ++r) {
    uint32_t face = row_start;
    for (uint32_t col = 0; col < spec.width; ++col) {
      const Point2 q = spec.CellCentre(col, first_row + r);
      const MeshWalkOutcome w = Walk(mesh, face, q);
      face = w.face;
      if (col == 0) row_start = face;
      *out++ = CellValue(mesh, spec.interpolation, spec.nodata, w, q);
    }
  }
}

void RenderPoints(const ServingMesh& mesh, uint32_t hint,
                  std::span<const Point2> points, size_t row_length,
                  Interpolation how, double nodata, double* out) {
  ScanPoints(
      mesh, hint, points, row_length, nodata,
      [&](const MeshWalkOutcome& w, const Point2& q) {
        return CellValue(mesh, how, nodata, w, q);
      },
      out);
}

void RenderGradients(const ServingMesh& mesh, uint32_t hint,
                     std::span<const Point2> points, size_t row_length,
                     FacetGradient* out) {
  ScanPoints(
      mesh, hint, points, row_length, FacetGradient{},
      [&](const MeshWalkOutcome& w, const Point2&) {
        const uint32_t f = ClosedDomainFace(mesh, w);
        if (!mesh.has_values() || f == ServingMesh::kNoFace) {
          return FacetGradient{};
        }
        return GradientOf(mesh, f);
      },
      out);
}

}  // namespace locator
