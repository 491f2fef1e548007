#include "server/app/surface_convert.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/input_text.h"
#include "common/status_macros.h"
#include "server/core/geometry/wide_math.h"

namespace locator {
namespace {

v1::ProfilePointKind ToKind(ProfilePointKind kind) {
  switch (kind) {
    case ProfilePointKind::kLineVertex:
      return v1::PROFILE_POINT_KIND_LINE_VERTEX;
    case ProfilePointKind::kEdgeCrossing:
      return v1::PROFILE_POINT_KIND_EDGE_CROSSING;
    case ProfilePointKind::kMeshVertex:
      return v1::PROFILE_POINT_KIND_MESH_VERTEX;
    case ProfilePointKind::kSample:
      return v1::PROFILE_POINT_KIND_SAMPLE;
  }
  return v1::PROFILE_POINT_KIND_UNSPECIFIED;
}

void ToProfilePoint(const ProfilePoint& p, v1::ProfilePoint* out) {
  out->set_kind(ToKind(p.kind));
  out->mutable_point()->set_x(p.point.x);
  out->mutable_point()->set_y(p.point.y);
  out->set_distance(p.distance);
  out->set_segment(p.segment);
  if (p.has_value) out->set_value(p.value);
  out->set_triangle_id(p.triangle_id);
}

v1::LocationType ToGapReason(LocationType reason) {
  return reason == LocationType::kOutsideDomain
             ? v1::LOCATION_TYPE_OUTSIDE_DOMAIN
             : v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL;
}

Status GridShape(const v1::GridRequest& request, RasterSpec* spec) {
  const bool sized = request.width() != 0 || request.height() != 0;
  const double cell = request.cell_size();
  if (sized == (cell != 0)) {
    return Status::InvalidArgument(
        "a grid needs either width and height or cell_size, not " +
        std::string(sized ? "both" : "neither"));
  }
  if (sized) {
    if (request.width() == 0 || request.height() == 0) {
      return Status::InvalidArgument("a grid needs width and height >= 1");
    }
    spec->width = request.width();
    spec->height = request.height();
    return Status::OK();
  }
  if (!std::isfinite(cell) || cell <= 0) {
    return Status::InvalidArgument("cell_size must be finite and positive");
  }
  BoundingBox& box = spec->box;
  // Step() and AddProduct() hold a box wider than the largest double.
  const double columns = std::ceil(Step(box.min_x, box.max_x, cell));
  const double rows = std::ceil(Step(box.min_y, box.max_y, cell));
  constexpr double kMaxSide = std::numeric_limits<uint32_t>::max();
  if (!(columns <= kMaxSide) || !(rows <= kMaxSide)) {
    return Status::ResourceExhausted("cell_size " + NumberText(cell) +
                                     " makes a grid of " + NumberText(columns) +
                                     " x " + NumberText(rows) + " cells");
  }
  spec->width = static_cast<uint32_t>(std::max(columns, 1.0));
  spec->height = static_cast<uint32_t>(std::max(rows, 1.0));
  box.max_x = AddProduct(box.min_x, spec->width, cell);
  box.min_y = AddProduct(box.max_y, spec->height, -cell);
  if (!std::isfinite(box.max_x) || !std::isfinite(box.min_y)) {
    return Status::InvalidArgument(
        "cell_size " + NumberText(cell) +
        " grows the box to whole cells beyond the largest double, " +
        NumberText(std::numeric_limits<double>::max()) +
        ": the box's east and south edges, min_x + width x cell_size and "
        "max_y - height x cell_size, must stay within it");
  }
  return Status::OK();
}

}  // namespace

StatusOr<Interpolation> FromInterpolation(int value) {
  switch (value) {
    case v1::INTERPOLATION_UNSPECIFIED:
    case v1::INTERPOLATION_LINEAR:
      return Interpolation::kLinear;
    case v1::INTERPOLATION_NATURAL_NEIGHBOR:
      return Interpolation::kNaturalNeighbor;
    case v1::INTERPOLATION_NEAREST:
      return Interpolation::kNearest;
  }
  return Status::InvalidArgument("unknown interpolation " +
                                 std::to_string(value));
}

std::vector<Point2> FromProfileRequest(const v1::ProfileRequest& request) {
  std::vector<Point2> line;
  line.reserve(request.vertices_size());
  for (const v1::Point& p : request.vertices()) {
    line.push_back(Point2{p.x(), p.y()});
  }
  return line;
}

void ToProfileResponse(const Profile& profile, v1::ProfileResponse* response) {
  response->mutable_breakpoints()->Reserve(
      static_cast<int>(profile.breakpoints.size()));
  for (const ProfilePoint& p : profile.breakpoints) {
    ToProfilePoint(p, response->add_breakpoints());
  }
  for (const ProfilePoint& p : profile.samples) {
    ToProfilePoint(p, response->add_samples());
  }
  for (const ProfileGap& gap : profile.gaps) {
    v1::ProfileGap* out = response->add_gaps();
    out->set_from_distance(gap.from_distance);
    out->set_to_distance(gap.to_distance);
    out->set_reason(ToGapReason(gap.reason));
  }
  response->set_length(profile.length);
  response->set_crossings(profile.crossings);
}

Status FromGridRequest(const v1::GridRequest& request, uint64_t max_cells,
                       RasterSpec* spec) {
  if (!request.has_box()) return Status::InvalidArgument("box is required");
  const v1::BoundingBox& b = request.box();
  spec->box = BoundingBox{b.min_x(), b.min_y(), b.max_x(), b.max_y()};
  spec->nodata = request.has_nodata()
                     ? request.nodata()
                     : std::numeric_limits<double>::quiet_NaN();
  ASSIGN_OR_RETURN(spec->interpolation,
                   FromInterpolation(request.interpolation()));
  RETURN_IF_ERROR(CheckRasterBox(spec->box));
  RETURN_IF_ERROR(GridShape(request, spec));
  if (spec->cells() > max_cells) {
    return Status::ResourceExhausted(
        "a grid of " + std::to_string(spec->width) + " x " +
        std::to_string(spec->height) + " = " + std::to_string(spec->cells()) +
        " cells exceeds this server's limit of " + std::to_string(max_cells) +
        " cells per request");
  }
  return CheckRasterSpec(*spec);
}

void ToGridHeader(const RasterSpec& spec, const std::string& crs_wkt,
                  v1::GridHeader* header) {
  header->set_width(spec.width);
  header->set_height(spec.height);
  v1::BoundingBox* box = header->mutable_box();
  box->set_min_x(spec.box.min_x);
  box->set_min_y(spec.box.min_y);
  box->set_max_x(spec.box.max_x);
  box->set_max_y(spec.box.max_y);
  header->set_cell_width(spec.cell_width());
  header->set_cell_height(spec.cell_height());
  header->set_nodata(spec.nodata);
  header->set_crs_wkt(crs_wkt);
}

uint32_t GridRowsPerBlock(const RasterSpec& spec) {
  return static_cast<uint32_t>(
      std::max<size_t>(1, kGridBlockValues / spec.width));
}

}  // namespace locator
