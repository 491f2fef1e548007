#include "tests/server/main/hostile/hostile_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace locator::test {
namespace {

// Points farther out are checked for shape only: their computed positions
// (a crossing on a line 1e160 long) carry absolute errors far beyond the
// dataset's scale.
constexpr double kModerate = 1e12;
// At most this many cells of a grid are compared with CGAL.
constexpr int64_t kCellsChecked = 4096;
// Relative tolerances of interpolated values against the exact plane (the
// natural-neighbour weights are computed in double).
constexpr double kLinearTolerance = 1e-9;
constexpr double kNaturalNeighborTolerance = 1e-6;

bool Moderate(const Point2& p) {
  return std::abs(p.x) <= kModerate && std::abs(p.y) <= kModerate;
}

bool InsideHull(LocationType type) {
  return type == LocationType::kFace || type == LocationType::kEdge ||
         type == LocationType::kVertex;
}

std::string Text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string At(const Point2& p) {
  return "(" + Text(p.x) + ", " + Text(p.y) + ")";
}

bool SameDouble(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

}  // namespace

DatasetOracle::DatasetOracle(std::string name,
                             std::unique_ptr<Reference> reference, bool plane)
    : name_(std::move(name)), reference_(std::move(reference)), plane_(plane) {
  const Dataset& dataset = reference_->dataset();
  for (const Point2& p : dataset.points) box_.Extend(p);
  values_.insert(dataset.values.begin(), dataset.values.end());
  if (!dataset.values.empty()) {
    const auto [lo, hi] =
        std::minmax_element(dataset.values.begin(), dataset.values.end());
    min_value_ = *lo;
    max_value_ = *hi;
  }
}

Point2 DatasetOracle::Inside(double u, double v) const {
  // The middle 80% of the box: inside the hull of both test datasets.
  return {box_.min_x + (0.1 + 0.8 * u) * box_.width(),
          box_.min_y + (0.1 + 0.8 * v) * box_.height()};
}

std::string DatasetOracle::CheckStructure(const LocateResult& got,
                                          const AnswerParts& parts) const {
  const auto in_range = [](int64_t id, uint64_t bound) {
    return id >= 0 && static_cast<uint64_t>(id) < bound;
  };
  const uint64_t vertices = reference_->dataset().points.size();
  if (got.type == LocationType::kOutsideDomain) {
    return "OUTSIDE_DOMAIN in a dataset without a domain";
  }
  if (!in_range(got.triangle_id, triangles_)) {
    return "triangle id " + std::to_string(got.triangle_id) + " outside [0, " +
           std::to_string(triangles_) + ")";
  }
  if (parts.vertex_ids) {
    for (int64_t id : got.vertex_ids) {
      if (!in_range(id, vertices)) {
        return "vertex id " + std::to_string(id) + " outside [0, " +
               std::to_string(vertices) + ")";
      }
    }
  }
  if (parts.barycentric && InsideHull(got.type)) {
    const auto& w = got.barycentric;
    const bool in_range = std::all_of(w.begin(), w.end(), [](double x) {
      return x >= -kLinearTolerance && x <= 1 + kLinearTolerance;
    });
    if (!in_range || std::abs(w[0] + w[1] + w[2] - 1) > kLinearTolerance) {
      return "barycentric (" + Text(w[0]) + ", " + Text(w[1]) + ", " +
             Text(w[2]) + ")";
    }
  }
  return "";
}

std::string DatasetOracle::CheckLocation(const std::optional<Point2>& q,
                                         v1::Interpolation how,
                                         const LocateResult& got,
                                         const AnswerParts& parts) const {
  const bool has_ids = parts.vertex_ids;
  if (std::string problem = CheckStructure(got, parts); !problem.empty()) {
    return problem;
  }
  const bool inside = InsideHull(got.type);
  if (q.has_value()) {
    const LocateResult want = reference_->Locate(*q);
    if (got.type != want.type) {
      return std::string("type ") + std::string(LocationTypeName(got.type)) +
             ", CGAL says " + std::string(LocationTypeName(want.type));
    }
    if (want.type == LocationType::kFace &&
        got.triangle_id != want.triangle_id) {
      return "triangle " + std::to_string(got.triangle_id) + ", CGAL says " +
             std::to_string(want.triangle_id);
    }
    bool agrees = !has_ids || reference_->Agrees(*q, got, want);
    // A batch row names no hull edge: some edge of its hull triangle,
    // taken counter-clockwise, must see q.
    for (int corner = 0; corner < 3 && !agrees && !parts.hull_edge &&
                         want.type == LocationType::kOutsideConvexHull;
         ++corner) {
      LocateResult with_edge = got;
      with_edge.hull_edge_ids = {got.vertex_ids[corner],
                                 got.vertex_ids[(corner + 1) % 3]};
      agrees = reference_->Agrees(*q, with_edge, want);
    }
    if (!agrees) return "not the location CGAL reports";
    if (inside && parts.value && how != v1::INTERPOLATION_NATURAL_NEIGHBOR &&
        how != v1::INTERPOLATION_NEAREST && got.has_value &&
        std::abs(got.value - want.value) >
            kLinearTolerance * (1 + std::abs(want.value))) {
      return "value " + Text(got.value) + ", CGAL's triangle gives " +
             Text(want.value);
    }
  }
  if (!parts.value) return "";
  if (!inside) return got.has_value ? "a value outside the hull" : "";
  if (!got.has_value) return "no value inside the hull";
  if (how == v1::INTERPOLATION_NEAREST && has_ids) {
    const std::vector<double>& values = reference_->dataset().values;
    const bool of_a_corner =
        std::any_of(got.vertex_ids.begin(), got.vertex_ids.end(),
                    [&](int64_t id) { return got.value == values[id]; });
    if (!of_a_corner) return "a nearest value no corner has";
  }
  return CheckValue(q, how, got.value);
}

std::string DatasetOracle::CheckValue(const std::optional<Point2>& p,
                                      v1::Interpolation how,
                                      double value) const {
  if (!std::isfinite(value)) return "value " + Text(value);
  const double slack =
      kLinearTolerance * (1 + std::abs(min_value_) + std::abs(max_value_));
  if (value < min_value_ - slack || value > max_value_ + slack) {
    return "value " + Text(value) + " outside the dataset's [" +
           Text(min_value_) + ", " + Text(max_value_) + "]";
  }
  if (how == v1::INTERPOLATION_NEAREST) {
    return values_.count(value) != 0 ? "" : "a nearest value no vertex has";
  }
  if (!plane_ || !p.has_value() || !Moderate(*p)) return "";
  const double want = TestValue(*p);
  const double tolerance = how == v1::INTERPOLATION_NATURAL_NEIGHBOR
                               ? kNaturalNeighborTolerance
                               : kLinearTolerance;
  if (std::abs(value - want) > tolerance * (1 + std::abs(max_value_))) {
    return "value " + Text(value) + " at " + At(*p) + ", the plane gives " +
           Text(want);
  }
  return "";
}

std::string DatasetOracle::CheckProfile(
    const v1::ProfileRequest& request,
    const v1::ProfileResponse& response) const {
  const double length = response.length();
  if (!std::isfinite(length) || length < 0) return "length " + Text(length);
  if (response.samples_size() != static_cast<int64_t>(request.samples())) {
    return std::to_string(response.samples_size()) + " samples, asked for " +
           std::to_string(request.samples());
  }
  const bool moderate_line =
      std::all_of(request.vertices().begin(), request.vertices().end(),
                  [](const v1::Point& v) {
                    return Moderate({v.x(), v.y()});
                  });
  const auto check_points = [&](const auto& points,
                                bool samples) -> std::string {
    double last = 0;
    for (int i = 0; i < points.size(); ++i) {
      const v1::ProfilePoint& p = points[i];
      const std::string where =
          (samples ? "sample " : "breakpoint ") + std::to_string(i) + ": ";
      const Point2 at{p.point().x(), p.point().y()};
      if (!IsFinite(at)) return where + "point " + At(at);
      if (!(p.distance() >= last && p.distance() <= length)) {
        return where + "distance " + Text(p.distance()) + " after " +
               Text(last) + " (length " + Text(length) + ")";
      }
      last = p.distance();
      if ((p.kind() == v1::PROFILE_POINT_KIND_SAMPLE) != samples ||
          p.kind() == v1::PROFILE_POINT_KIND_UNSPECIFIED) {
        return where + "kind " + std::to_string(p.kind());
      }
      if (p.triangle_id() < -1 ||
          p.triangle_id() >= static_cast<int64_t>(triangles_)) {
        return where + "triangle id " + std::to_string(p.triangle_id());
      }
      if (p.segment() + 1 >=
          std::max<uint32_t>(2,
                             static_cast<uint32_t>(request.vertices_size()))) {
        return where + "segment " + std::to_string(p.segment());
      }
      if (p.has_value()) {
        const std::string problem = CheckValue(
            moderate_line && request.crs().empty() ? std::optional<Point2>(at)
                                                   : std::nullopt,
            request.interpolation(), p.value());
        if (!problem.empty()) return where + problem;
      }
    }
    return "";
  };
  if (std::string problem = check_points(response.breakpoints(), false);
      !problem.empty()) {
    return problem;
  }
  if (std::string problem = check_points(response.samples(), true);
      !problem.empty()) {
    return problem;
  }
  const auto crossings = std::count_if(
      response.breakpoints().begin(), response.breakpoints().end(),
      [](const v1::ProfilePoint& p) {
        return p.kind() != v1::PROFILE_POINT_KIND_LINE_VERTEX;
      });
  if (static_cast<uint64_t>(crossings) != response.crossings()) {
    return "crossings " + std::to_string(response.crossings()) + ", but " +
           std::to_string(crossings) + " crossing breakpoints";
  }
  double last = 0;
  for (const v1::ProfileGap& gap : response.gaps()) {
    if (!(gap.from_distance() >= last &&
          gap.to_distance() >= gap.from_distance() &&
          gap.to_distance() <= length) ||
        gap.reason() != v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL) {
      return "gap [" + Text(gap.from_distance()) + ", " +
             Text(gap.to_distance()) + "] reason " +
             std::to_string(gap.reason());
    }
    last = gap.to_distance();
  }
  return "";
}

std::string DatasetOracle::CheckGrid(const v1::GridRequest& request,
                                     const v1::GridResponse& response) const {
  const v1::GridHeader& header = response.header();
  const int64_t width = header.width(), height = header.height();
  if (width <= 0 || height <= 0 ||
      (request.width() != 0 &&
       (width != request.width() || height != request.height()))) {
    return "a " + std::to_string(width) + " x " + std::to_string(height) +
           " grid for " + std::to_string(request.width()) + " x " +
           std::to_string(request.height());
  }
  if (response.values_size() != width * height ||
      response.rows() != header.height() || response.first_row() != 0) {
    return std::to_string(response.values_size()) + " values in " +
           std::to_string(response.rows()) + " rows for " +
           std::to_string(width) + " x " + std::to_string(height);
  }
  const v1::BoundingBox& b = header.box();
  const double cw = header.cell_width(), ch = header.cell_height();
  if (!IsFinite({b.min_x(), b.min_y()}) || !IsFinite({b.max_x(), b.max_y()}) ||
      !(cw > 0) || !(ch > 0) || !std::isfinite(cw) || !std::isfinite(ch)) {
    return "header box or cells not finite and positive: " +
           header.ShortDebugString();
  }
  const double nodata = request.has_nodata()
                            ? request.nodata()
                            : std::numeric_limits<double>::quiet_NaN();
  if (!SameDouble(header.nodata(), nodata)) {
    return "nodata " + Text(header.nodata()) + ", asked for " + Text(nodata);
  }
  const bool nodata_outside_values =
      std::isnan(nodata) || nodata < min_value_ || nodata > max_value_;
  const int64_t stride = std::max<int64_t>(1, width * height / kCellsChecked);
  for (int64_t cell = 0; cell < width * height; cell += stride) {
    const int64_t row = cell / width, col = cell % width;
    const double v = response.values(static_cast<int>(cell));
    const Point2 centre{b.min_x() + (col + 0.5) * cw,
                        b.max_y() - (row + 0.5) * ch};
    const std::string where = "cell (" + std::to_string(col) + ", " +
                              std::to_string(row) + ") at " + At(centre) + ": ";
    const bool is_nodata = SameDouble(v, nodata);
    const bool known = IsFinite(centre) && Moderate(centre);
    if (known) {
      const LocationType type = reference_->Locate(centre).type;
      if (type == LocationType::kOutsideConvexHull && !is_nodata) {
        return where + "value " + Text(v) + " outside the hull";
      }
      if (type == LocationType::kFace && is_nodata && nodata_outside_values) {
        return where + "nodata inside the hull";
      }
    }
    if (!is_nodata) {
      const std::string problem =
          CheckValue(known ? std::optional<Point2>(centre) : std::nullopt,
                     request.interpolation(), v);
      if (!problem.empty()) return where + problem;
    }
  }
  return "";
}

}  // namespace locator::test
