#include "server/core/geometry/segment_crossing.h"

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "server/core/geometry/wide_math.h"

namespace locator {

namespace {

// (v - u) x (w - u) in Wide, and into *magnitude the sum of its terms'
// magnitudes: its rounding error is a few Wide epsilons times that.
Wide CrossWithMagnitude(const Point2& u, const Point2& v, const Point2& w,
                        Wide* magnitude) {
  const Wide left = (Wide{v.x} - u.x) * (Wide{w.y} - u.y);
  const Wide right = (Wide{v.y} - u.y) * (Wide{w.x} - u.x);
  *magnitude = std::abs(left) + std::abs(right);
  return left - right;
}

// The fraction along a->b where it crosses the line uv, into *s; false if
// rounding may have moved it by more than 2^-50. With a and b on opposite
// sides, s = oa / (oa - ob) is off by at most the cross products' errors
// over |oa - ob|.
bool WideFraction(const Point2& u, const Point2& v, const Point2& a,
                  const Point2& b, Wide* s) {
  Wide magnitude_a = 0;
  Wide magnitude_b = 0;
  const Wide oa = CrossWithMagnitude(u, v, a, &magnitude_a);
  const Wide ob = CrossWithMagnitude(u, v, b, &magnitude_b);
  const Wide denominator = oa - ob;
  constexpr Wide kRoundoff = 8 * std::numeric_limits<Wide>::epsilon();
  constexpr Wide kTolerance = 0x1p-50;
  if (!(kRoundoff * (magnitude_a + magnitude_b) <=
        kTolerance * std::abs(denominator))) {
    return false;
  }
  *s = std::clamp(oa / denominator, Wide{0}, Wide{1});
  return true;
}

// The crossing from exact rationals, rounded once per coordinate.
Point2 ExactCrossing(const Point2& p, const Point2& q, const Point2& a,
                     const Point2& b) {
  using Exact = CGAL::Exact_rational;
  // The return type is spelled out: with `auto`, an expression-template
  // number type would return references to the lambda's temporaries.
  const auto cross = [](const Point2& u, const Point2& v,
                        const Point2& w) -> Exact {
    return (Exact(v.x) - u.x) * (Exact(w.y) - u.y) -
           (Exact(v.y) - u.y) * (Exact(w.x) - u.x);
  };
  const Exact oa = cross(p, q, a);
  const Exact ob = cross(p, q, b);
  // Both on the line pq: no single crossing (excluded by the precondition;
  // a division by zero would raise SIGFPE in GMP).
  if (oa == ob) return Midpoint(a, b);
  const Exact s = oa / (oa - ob);
  return {CGAL::to_double(Exact(Exact(a.x) + s * (Exact(b.x) - a.x))),
          CGAL::to_double(Exact(Exact(a.y) + s * (Exact(b.y) - a.y)))};
}

// v clamped into [e0, e1] (either order) and [s0, s1].
double Within(double v, double e0, double e1, double s0, double s1) {
  return std::clamp(v, std::max(std::min(e0, e1), std::min(s0, s1)),
                    std::min(std::max(e0, e1), std::max(s0, s1)));
}

}  // namespace

Point2 SegmentCrossing(const Point2& p, const Point2& q, const Point2& a,
                       const Point2& b) {
  const bool ab_shorter = SquaredDistanceWide(a, b) < SquaredDistanceWide(p, q);
  Wide f = 0;
  const Point2 crossing =
      ab_shorter ? (WideFraction(p, q, a, b, &f) ? Lerp(a, b, f)
                                                 : ExactCrossing(p, q, a, b))
                 : (WideFraction(a, b, p, q, &f) ? Lerp(p, q, f)
                                                 : ExactCrossing(a, b, p, q));
  return {Within(crossing.x, a.x, b.x, p.x, q.x),
          Within(crossing.y, a.y, b.y, p.y, q.y)};
}

}  // namespace locator
