#include "server/tiles/quantized_mesh/wgs84.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace locator {
namespace {

double Dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double Norm(const Vec3& a) { return std::sqrt(Dot(a, a)); }

Vec3 Scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

Vec3 ToScaledSpace(const Vec3& p) {
  return {p[0] / kWgs84Radii[0], p[1] / kWgs84Radii[1], p[2] / kWgs84Radii[2]};
}

// How far along the unit `direction` (scaled space) the occlusion point
// must be to hide `position`: EllipsoidalOccluder's computeMagnitude.
double Magnitude(const Vec3& position, const Vec3& direction) {
  const Vec3 scaled = ToScaledSpace(position);
  double magnitude_squared = Dot(scaled, scaled);
  double magnitude = std::sqrt(magnitude_squared);
  const Vec3 unit = Scaled(scaled, 1 / magnitude);
  magnitude_squared = std::max(1.0, magnitude_squared);
  magnitude = std::max(1.0, magnitude);
  const double cos_alpha = Dot(unit, direction);
  const Vec3 cross = {unit[1] * direction[2] - unit[2] * direction[1],
                      unit[2] * direction[0] - unit[0] * direction[2],
                      unit[0] * direction[1] - unit[1] * direction[0]};
  const double sin_alpha = Norm(cross);
  const double cos_beta = 1 / magnitude;
  const double sin_beta = std::sqrt(magnitude_squared - 1) * cos_beta;
  return 1 / (cos_alpha * cos_beta - sin_alpha * sin_beta);
}

}  // namespace

Vec3 GeodeticToEcef(double lon, double lat, double height) {
  const double a = kWgs84Radii[0], b = kWgs84Radii[2];
  const double e2 = 1 - (b * b) / (a * a);
  const double phi = lat * std::numbers::pi / 180;
  const double lambda = lon * std::numbers::pi / 180;
  const double n = a / std::sqrt(1 - e2 * std::sin(phi) * std::sin(phi));
  return {(n + height) * std::cos(phi) * std::cos(lambda),
          (n + height) * std::cos(phi) * std::sin(lambda),
          (n * (1 - e2) + height) * std::sin(phi)};
}

Sphere BoundingSphere(std::span<const Vec3> points) {
  if (points.empty()) return Sphere();
  Vec3 low = points[0], high = points[0];
  for (const Vec3& p : points) {
    for (int i = 0; i < 3; ++i) {
      low[i] = std::min(low[i], p[i]);
      high[i] = std::max(high[i], p[i]);
    }
  }
  Sphere s;
  for (int i = 0; i < 3; ++i) s.centre[i] = (low[i] + high[i]) / 2;
  for (const Vec3& p : points) {
    const Vec3 d = {p[0] - s.centre[0], p[1] - s.centre[1], p[2] - s.centre[2]};
    s.radius = std::max(s.radius, Norm(d));
  }
  return s;
}

Vec3 HorizonOcclusionPoint(std::span<const Vec3> points,
                           const Vec3& direction) {
  Vec3 unit = ToScaledSpace(direction);
  const double length = Norm(unit);
  unit = length > 0 ? Scaled(unit, 1 / length) : Vec3{1, 0, 0};
  constexpr double kFarAway = 1000;
  double result = 0;
  for (const Vec3& p : points) {
    const double m = Magnitude(p, unit);
    if (!(m > 0) || !std::isfinite(m)) return Scaled(unit, kFarAway);
    result = std::max(result, m);
  }
  return Scaled(unit, result > 0 ? result : 1);
}

}  // namespace locator
