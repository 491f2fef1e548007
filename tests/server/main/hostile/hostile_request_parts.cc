#include "tests/server/main/hostile/hostile_request_parts.h"

#include <cmath>

#include "tests/server/main/hostile/hostile_requests.h"

namespace locator::test {
namespace {

using Code = grpc::StatusCode;

// Lon/lat around the utm dataset's hill (15°E, 49.6525°N, ±2.8 km).
constexpr BoundingBox kHillLonLat{14.955, 49.62, 15.045, 49.685};
// Dataset names in an HTTP path longer than this may be refused by the
// HTTP server itself (its header limit is 8 KiB).
constexpr size_t kLongPath = 1024;

constexpr int kHostileInterpolationValues[kHostileInterpolations] = {4, 99, -7};

}  // namespace

Target DrawTarget(CaseDraw& draw, const HostileServer& server, bool with_crs,
                  Transport transport, Expectation* expect) {
  Target target;
  static const std::vector<std::string> names = HostileDatasetNames();
  if (const auto hostile =
          draw.Hostile(kFieldDataset, names.size() - kCostlyDatasetNames)) {
    target.dataset = names[*hostile];
    target.summary = "dataset '" + Shorten(target.dataset, 40) + "'";
    expect->Require(Code::NOT_FOUND, {"dataset"});
    if (transport == Transport::kHttp && target.dataset.size() > kLongPath) {
      expect->AllowHttpStatus(414).AllowHttpStatus(431);
    }
    target.frame = server.plain().box();
    return target;
  }
  const double pick = draw.Uniform(0, 1);
  target.dataset = pick < 0.25 ? "" : pick < 0.5 ? "plain" : "utm";
  target.oracle = server.OracleFor(target.dataset);
  target.summary = "dataset '" + target.dataset + "'";
  const std::vector<RequestCrs>& list = server.request_crs();
  if (const auto hostile =
          with_crs ? draw.Hostile(kFieldCrs, list.size() - kCostlyRequestCrs)
                   : std::nullopt) {
    target.crs = &list[*hostile];
  } else if (with_crs && target.oracle == &server.utm() && draw.Chance(0.5)) {
    target.crs = &list[draw.Chance(0.5) ? 0 : 2];  // EPSG:32633, EPSG:4326
  }
  const CrsKind kind =
      target.crs != nullptr ? target.crs->kind : CrsKind::kDatasetOwn;
  target.frame =
      kind == CrsKind::kDatasetOwn ? target.oracle->box() : kHillLonLat;
  target.points_known = kind == CrsKind::kDatasetOwn;
  if (target.crs == nullptr) return target;
  target.summary += " crs " + Shorten(target.crs->label, 60);
  const std::vector<std::string> crs_only = {"crs"};
  if (target.oracle == &server.plain()) {
    // The plain dataset has no CRS to transform to.
    expect->Require(Code::INVALID_ARGUMENT, crs_only);
    return target;
  }
  switch (kind) {
    case CrsKind::kRefused:
      expect->Require(Code::INVALID_ARGUMENT, crs_only)
          .Allow(Code::PERMISSION_DENIED, crs_only);
      break;
    case CrsKind::kHuge:
      expect->Require(Code::INVALID_ARGUMENT, crs_only)
          .Allow(Code::RESOURCE_EXHAUSTED, crs_only);
      break;
    case CrsKind::kMaybe:
      expect->Allow(Code::INVALID_ARGUMENT, crs_only)
          .Allow(Code::PERMISSION_DENIED, crs_only);
      break;
    case CrsKind::kDatasetOwn:
    case CrsKind::kLonLat:
      break;
  }
  return target;
}

Point2 BenignPoint(CaseDraw& draw, const Target& target) {
  if (target.points_known && target.oracle != nullptr && draw.Chance(0.2)) {
    const std::vector<Point2>& points =
        target.oracle->reference().dataset().points;
    const size_t k = draw.Below(points.size() - 1);
    if (draw.Chance(0.5)) return points[k];  // a vertex
    return {(points[k].x + points[k + 1].x) / 2,
            (points[k].y + points[k + 1].y) / 2};
  }
  const BoundingBox& f = target.frame;
  return {f.min_x + draw.Uniform(-0.15, 1.15) * f.width(),
          f.min_y + draw.Uniform(-0.15, 1.15) * f.height()};
}

std::string DrawHostilePoint(CaseDraw& draw, Point2* p) {
  const std::vector<double>& coordinates = HostileCoordinates();
  std::string text;
  if (const auto i = draw.Hostile(kFieldX, coordinates.size())) {
    p->x = coordinates[*i];
    text += "x=" + DoubleName(p->x);
  }
  if (const auto i = draw.Hostile(kFieldY, coordinates.size())) {
    p->y = coordinates[*i];
    text += std::string(text.empty() ? "" : " ") + "y=" + DoubleName(p->y);
  }
  return text;
}

void ExpectPoint(const Point2& p, const Target& target,
                 const std::vector<std::string>& names, Expectation* expect) {
  if (target.oracle == nullptr) return;
  if (!IsFinite(p)) {
    expect->Require(Code::INVALID_ARGUMENT, names);
  } else if (target.crs != nullptr) {
    expect->Allow(Code::INVALID_ARGUMENT, kCrsNames);
  }
}

v1::Interpolation DrawInterpolation(CaseDraw& draw, const Target& target,
                                    Expectation* expect, std::string* summary) {
  if (const auto i =
          draw.Hostile(kFieldInterpolation, kHostileInterpolations)) {
    const int value = kHostileInterpolationValues[*i];
    if (target.oracle != nullptr) {
      expect->Require(Code::INVALID_ARGUMENT, {"interpolation"});
    }
    *summary += " interpolation " + std::to_string(value);
    return static_cast<v1::Interpolation>(value);
  }
  static constexpr v1::Interpolation kBenign[] = {
      v1::INTERPOLATION_UNSPECIFIED, v1::INTERPOLATION_LINEAR,
      v1::INTERPOLATION_NATURAL_NEIGHBOR, v1::INTERPOLATION_NEAREST};
  const v1::Interpolation how = kBenign[draw.Below(4)];
  *summary += std::string(" ") + v1::Interpolation_Name(how);
  return how;
}

std::string PointText(const Point2& p) {
  return "(" + DoubleName(p.x) + ", " + DoubleName(p.y) + ")";
}

}  // namespace locator::test
