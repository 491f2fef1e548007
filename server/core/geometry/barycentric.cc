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

template <class Real>
constexpr Real kRoundoff = 8 * std::numeric_limits<Real>::epsilon();

// The cross product (u - o) x (v - o) in `Real`, with *magnitude the sum of
// its terms' magnitudes (OrientationFilter(u, v, o) computes it alike).
template <class Real>
Real Cross(const Point2& o, const Point2& u, const Point2& v, Real* magnitude) {
  const Real left = (Real{u.x} - o.x) * (Real{v.y} - o.y);
  const Real right = (Real{u.y} - o.y) * (Real{v.x} - o.x);
  *magnitude = std::abs(left) + std::abs(right);
  return left - right;
}

// Whether a triangle's cross product `area` (of terms summing to
// `magnitude`) is resolved in `Real`: its rounding error (a few epsilon
// times the magnitude of its terms) is small against it, and the terms lie
// in the range [min_magnitude, max_magnitude] where that error is relative.
// Each difference and product rounds once: a relative error of a few
// epsilon per term; 8 epsilon leaves a margin.
template <class Real>
bool AreaResolves(Real area, Real magnitude, Real min_magnitude,
                  Real max_magnitude) {
  return magnitude >= min_magnitude && magnitude <= max_magnitude &&
         std::abs(area) > kRoundoff<Real> * magnitude;
}

// Barycentric coordinates into *result from the resolved `area` cross and
// the crosses (q, b, c) and (q, c, a) with their magnitudes; false when
// they are not within kTolerance: a needle's area is small against its
// terms, so its coordinates need more precision than a plump triangle's.
template <class Real>
bool CoordinatesFromCrosses(Real area, Real magnitude, Real cross_a,
                            Real magnitude_a, Real cross_b, Real magnitude_b,
                            std::array<double, 3>* result) {
  const Real ba = cross_a / area;
  const Real bb = cross_b / area;
  // A coordinate n / area is off by (the error of n + |n / area| times
  // that of the area) / |area|; at most kTolerance.
  constexpr Real kTolerance = 0x1p-40;
  const Real bound = kTolerance / kRoundoff<Real> * std::abs(area);
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

// Barycentric coordinates of q in (a, b, c) from cross products in `Real`,
// into *result; false when Real cannot resolve them to within kTolerance
// (AreaResolves, CoordinatesFromCrosses), or a coordinate is not finite.
template <class Real>
bool BarycentricIn(const Point2& a, const Point2& b, const Point2& c,
                   const Point2& q, Real min_magnitude, Real max_magnitude,
                   std::array<double, 3>* result) {
  Real magnitude = 0;
  const Real area = Cross(a, b, c, &magnitude);
  if (!AreaResolves(area, magnitude, min_magnitude, max_magnitude)) {
    return false;
  }
  Real magnitude_a = 0;
  Real magnitude_b = 0;
  const Real cross_a = Cross(q, b, c, &magnitude_a);
  const Real cross_b = Cross(q, c, a, &magnitude_b);
  return CoordinatesFromCrosses(area, magnitude, cross_a, magnitude_a, cross_b,
                                magnitude_b, result);
}

// Terms of at least 2^-960 round with an error far above the subnormal
// range; at most 2^1020 leaves room for the sums.
constexpr double kMinDoubleTerms = 0x1p-960;
constexpr double kMaxDoubleTerms = 0x1p1020;

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
  if (BarycentricIn<double>(a, b, c, q, kMinDoubleTerms, kMaxDoubleTerms,
                            &result) ||
      BarycentricIn<long double>(
          a, b, c, q, 0, std::numeric_limits<long double>::max(), &result)) {
    return result;
  }
  return ExactBarycentric(a, b, c, q);
}

TriangleBarycentric::TriangleBarycentric(const Point2& a, const Point2& b,
                                         const Point2& c)
    : a_(a), b_(b), c_(c) {
  area_ = Cross(a, b, c, &magnitude_);
  resolves_ = AreaResolves(area_, magnitude_, kMinDoubleTerms, kMaxDoubleTerms);
}

std::array<double, 3> TriangleBarycentric::Of(
    const Point2& q, const OrientationFilter& bcq,
    const OrientationFilter& caq) const {
  std::array<double, 3> result;
  if (resolves_ &&
      CoordinatesFromCrosses(area_, magnitude_, bcq.determinant, bcq.terms,
                             caq.determinant, caq.terms, &result)) {
    return result;
  }
  return Barycentric(a_, b_, c_, q);
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
