#include "server/core/surface/raster_render.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/input_text.h"
#include "common/status_macros.h"
#include "server/core/geometry/wide_math.h"
#include "server/core/mesh/mesh_walk.h"
#include "server/core/mesh/scan_face.h"
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

// Places each of `count` points in rows of `row_length` (the last may be
// shorter; point(row, column), in scan order: see RenderPoints) and writes
// `inside(scan, q)` for a point q inside the face `scan` holds, `at(w, q)`
// for one that the walk `w` reached, or `none` for a point that is not
// finite.
template <class T, class PointAt, class Inside, class AtPoint>
void ScanPoints(const ServingMesh& mesh, uint32_t hint, size_t count,
                PointAt point, size_t row_length, T none, Inside inside,
                AtPoint at, T* out) {
  uint32_t row_start = hint;
  ScanFace scan(mesh);
  for (size_t row = 0, first = 0; first < count; ++row, first += row_length) {
    // A row's first point is next to the previous row's, not to that row's
    // last point a tile's width away.
    uint32_t face = row_start;
    bool row_started = false;
    scan.Forget();
    const size_t columns = std::min(row_length, count - first);
    for (size_t column = 0; column < columns; ++column) {
      const Point2 q = point(row, column);
      if (!IsFinite(q)) {
        *out++ = none;
        continue;
      }
      if (scan.Holds(q)) {
        face = scan.face();
        *out++ = inside(scan, q);
      } else {
        const MeshWalkOutcome w = scan.WalkTo(q, face);
        face = w.face;
        *out++ = at(w, q);
      }
      if (!row_started) row_start = face;
      row_started = true;
    }
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

// Renders the value at `count` points (point(row, column), in scan order)
// into `out` as RenderPoints describes.
template <class PointAt>
void RenderScan(const ServingMesh& mesh, uint32_t hint, size_t count,
                PointAt point, size_t row_length, Interpolation how,
                double nodata, double* out) {
  const bool linear = how == Interpolation::kLinear && mesh.has_values();
  ScanPoints(
      mesh, hint, count, point, row_length, nodata,
      [&](ScanFace& scan, const Point2& q) {
        if (linear) return scan.LinearValue(q);
        return CellValue(mesh, how, nodata,
                         MeshWalkOutcome{.face = scan.face(),
                                         .type = LocationType::kFace,
                                         .feature = -1},
                         q);
      },
      [&](const MeshWalkOutcome& w, const Point2& q) {
        return CellValue(mesh, how, nodata, w, q);
      },
      out);
}

}  // namespace

void RenderRows(const ServingMesh& mesh, uint32_t hint, const RasterSpec& spec,
                uint32_t first_row, uint32_t rows, double* out) {
  // A cell's x depends on its column alone and its y on its row alone.
  std::vector<double> column_x(spec.width);
  for (uint32_t col = 0; col < spec.width; ++col) {
    column_x[col] = spec.CellCentre(col, first_row).x;
  }
  std::vector<double> row_y(rows);
  for (uint32_t r = 0; r < rows; ++r) {
    row_y[r] = spec.CellCentre(0, first_row + r).y;
  }
  RenderScan(
      mesh, hint, size_t{rows} * spec.width,
      [&](size_t row, size_t column) {
        return Point2{column_x[column], row_y[row]};
      },
      spec.width, spec.interpolation, spec.nodata, out);
}

void RenderPoints(const ServingMesh& mesh, uint32_t hint,
                  std::span<const Point2> points, size_t row_length,
                  Interpolation how, double nodata, double* out) {
  RenderScan(
      mesh, hint, points.size(),
      [&](size_t row, size_t column) {
        return points[row * row_length + column];
      },
      row_length, how, nodata, out);
}

void RenderGradients(const ServingMesh& mesh, uint32_t hint,
                     std::span<const Point2> points, size_t row_length,
                     FacetGradient* out) {
  const auto gradient = [&](uint32_t f) {
    return mesh.has_values() ? GradientOf(mesh, f) : FacetGradient{};
  };
  // A face's gradient, computed once for the points it holds.
  uint32_t last_face = ServingMesh::kNoFace;
  FacetGradient last_gradient;
  ScanPoints(
      mesh, hint, points.size(),
      [&](size_t row, size_t column) {
        return points[row * row_length + column];
      },
      row_length, FacetGradient{},
      [&](const ScanFace& scan, const Point2&) {
        if (scan.face() != last_face) {
          last_face = scan.face();
          last_gradient = gradient(last_face);
        }
        return last_gradient;
      },
      [&](const MeshWalkOutcome& w, const Point2&) {
        const uint32_t f = ClosedDomainFace(mesh, w);
        return f == ServingMesh::kNoFace ? FacetGradient{} : gradient(f);
      },
      out);
}

}  // namespace locator
