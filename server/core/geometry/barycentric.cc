#include "server/core/geometry/barycentric.h"

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

// Barycentric coordinates of q in (a, b, c) from cross products in `Real`,
// into *result; false when Real cannot resolve them to within kTolerance:
// when a cross product's rounding error (a few epsilon times the magnitude
// of its terms) is too large against the area, or a term leaves the range
// where that error is relative (above max_magnitude, below min_magnitude),
// or a coordinate is not finite. A needle's area is small against its
// terms, so its coordinates need more precision than a plump triangle's.
template <class Real>
bool BarycentricIn(const Point2& a, const Point2& b, const Point2& c,
                   const Point2& q, Real min_magnitude, Real max_magnitude,
                   std::array<double, 3>* result) {
  auto cross = [](const Point2& o, const Point2& u, const Point2& v,
                  Real* magnitude) {
    const Real left = (Real{u.x} - o.x) * (Real{v.y} - o.y);
    const Real right = (Real{u.y} - o.y) * (Real{v.x} - o.x);
    *magnitude = std::abs(left) + std::abs(right);
    return left - right;
  };
  Real magnitude = 0;
  const Real area = cross(a, b, c, &magnitude);
  // Each difference and product rounds once: a relative error of a few
  // epsilon per term; 8 epsilon leaves a margin.
  constexpr Real kRoundoff = 8 * std::numeric_limits<Real>::epsilon();
  if (!(magnitude >= min_magnitude && magnitude <= max_magnitude &&
        std::abs(area) > kRoundoff * magnitude)) {
    return false;
  }
  Real magnitude_a = 0;
  Real magnitude_b = 0;
  const Real ba = cross(q, b, c, &magnitude_a) / area;
  const Real bb = cross(q, c, a, &magnitude_b) / area;
  // A coordinate n / area is off by (the error of n + |n / area| times
  // that of the area) / |area|; at most kTolerance.
  constexpr Real kTolerance = 0x1p-40;
  const Real bound = kTolerance / kRoundoff * std::abs(area);
  if (!(magnitude_a + std::abs(ba) * magnitude <= bound &&
        magnitude_b + std::abs(bb) * magnitude <= bound)) {
    return false;
  }
  *result = {static_cast<double>(ba), static_cast<double>(bb),
             static_cast<double>(1 - ba - bb)};
  for (const double coordinate : *result) {
    if (!std::isfinite(coordinate)) return false;
  }
  return true;
}

}  // namespace

// Barycentric coordinates of q in (a, b, c), to within 2^-40; the location
// type then pins the exact zeros and ones. The cross products square
// coordinate differences, so in double they overflow beyond ~1e154 and
// underflow below ~1e-154. Most triangles are well inside that range and
// plump enough for double; the rest take long double, whose exponent range
// covers every double and whose precision resolves needles 2^11 times
// thinner; and the thinnest needles (one spanning 1e-300..1e150, whose
// area in long double may be 0 or have the wrong sign) take
// ExactBarycentric.
std::array<double, 3> Barycentric(const Point2& a, const Point2& b,
                                  const Point2& c, const Point2& q) {
  std::array<double, 3> result;
  // Terms of at least 2^-960 round with an error far above the subnormal
  // range; at most 2^1020 leaves room for the sums.
  if (BarycentricIn<double>(a, b, c, q, 0x1p-960, 0x1p1020, &result) ||
      BarycentricIn<long double>(
          a, b, c, q, 0, std::numeric_limits<long double>::max(), &result)) {
    return result;
  }
  return ExactBarycentric(a, b, c, q);
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
