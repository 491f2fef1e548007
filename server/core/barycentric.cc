#include "server/core/barycentric.h"

#include <CGAL/Exact_rational.h>

#include <cmath>
#include <limits>

namespace locator {

namespace {

// Barycentric coordinates of q in (a, b, c) from exact rationals: the slow
// path of Barycentric(), for triangles whose area long double cannot
// resolve. The face is non-degenerate (CGAL's orientation is exact), so the
// area is not zero.
std::array<double, 3> ExactBarycentric(const Point2& a, const Point2& b,
                                       const Point2& c, const Point2& q) {
  using Exact = CGAL::Exact_rational;
  // The return type is spelled out: with `auto`, an expression-template
  // number type would return references to the lambda's temporaries.
  auto cross = [](const Point2& o, const Point2& u, const Point2& v) -> Exact {
    return (Exact(u.x) - o.x) * (Exact(v.y) - o.y) -
           (Exact(u.y) - o.y) * (Exact(v.x) - o.x);
  };
  const Exact area = cross(a, b, c);
  const Exact ba = cross(q, b, c) / area;
  const Exact bb = cross(q, c, a) / area;
  const Exact bc = Exact(1) - ba - bb;
  return {CGAL::to_double(ba), CGAL::to_double(bb), CGAL::to_double(bc)};
}

}  // namespace

// Barycentric coordinates of q in (a, b, c); the location type then pins
// the exact zeros and ones. In long double, because the cross products
// square coordinate differences: in double they overflow beyond ~1e154 and
// underflow below ~1e-154, and inf/inf or 0/0 would answer NaN. When the
// area is within long double's rounding error of its terms (a needle
// triangle spanning 1e-300..1e150), it may be 0 or have the wrong sign, so
// the answer comes from ExactBarycentric instead.
std::array<double, 3> Barycentric(const Point2& a, const Point2& b,
                                  const Point2& c, const Point2& q) {
  using Real = long double;
  auto cross = [](const Point2& o, const Point2& u, const Point2& v,
                  Real* magnitude) {
    const Real left = (Real{u.x} - o.x) * (Real{v.y} - o.y);
    const Real right = (Real{u.y} - o.y) * (Real{v.x} - o.x);
    if (magnitude != nullptr) *magnitude = std::abs(left) + std::abs(right);
    return left - right;
  };
  Real magnitude = 0;
  const Real area = cross(a, b, c, &magnitude);
  // Each difference and product rounds once: a relative error of a few
  // epsilon per term; 8 epsilon leaves a margin.
  constexpr Real kRelativeError = 8 * std::numeric_limits<Real>::epsilon();
  if (!(std::abs(area) > kRelativeError * magnitude)) {
    return ExactBarycentric(a, b, c, q);
  }
  const Real ba = cross(q, b, c, nullptr) / area;
  const Real bb = cross(q, c, a, nullptr) / area;
  const std::array<double, 3> result = {static_cast<double>(ba),
                                        static_cast<double>(bb),
                                        static_cast<double>(1 - ba - bb)};
  for (const double coordinate : result) {
    if (!std::isfinite(coordinate)) return ExactBarycentric(a, b, c, q);
  }
  return result;
}

std::array<double, 3> EdgeBarycentric(const std::array<Point2, 3>& corners,
                                      int edge, const Point2& q) {
  auto b = Barycentric(corners[0], corners[1], corners[2], q);
  const int next = edge == 2 ? 0 : edge + 1;
  const int prev = edge == 0 ? 2 : edge - 1;
  b[edge] = 0;
  const double sum = b[next] + b[prev];
  b[next] /= sum;
  b[prev] /= sum;
  return b;
}

}  // namespace locator
