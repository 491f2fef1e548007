// Arithmetic on finite doubles whose double intermediates could overflow
// to infinity or underflow to zero although the inputs and the answer are
// finite: the difference of -1e308 and 1e308, the square of 1e160, the
// product of two denormals. It is done in long double, whose exponent range
// holds every sum, difference and product of two (and of a few) doubles,
// and the answer is rounded back into the range of the doubles it lies
// between. Nothing here is on a locate's hot path; the hot paths compute in
// double and come here only when that overflowed (see ConvexSum).
//
// Thread-safety: pure functions and a value type.

#ifndef LOCATOR_CORE_WIDE_MATH_H_
#define LOCATOR_CORE_WIDE_MATH_H_

#include <algorithm>
#include <cmath>
#include <limits>

#include "locator/geometry.h"

namespace locator {

using Wide = long double;

// Squares of differences of doubles (|d| < 2^1025, d^2 < 2^2050) and their
// smallest products (2^-2148) must be representable.
static_assert(std::numeric_limits<Wide>::max_exponent >= 2100 &&
                  std::numeric_limits<Wide>::min_exponent <= -2200,
              "long double must have a wider exponent range than double");

// The largest finite double, as Wide.
constexpr Wide kMaxDouble = std::numeric_limits<double>::max();

// v rounded to double, +-infinity beyond the doubles (spelled out: the
// C++ conversion of an out-of-range value is undefined).
inline double Narrow(Wide v) {
  if (std::abs(v) <= kMaxDouble) return static_cast<double>(v);
  return v > 0 ? std::numeric_limits<double>::infinity()
               : -std::numeric_limits<double>::infinity();
}

// v clamped into [lo, hi] and rounded to double, for a v that lies there
// up to rounding (so the answer is finite).
inline double ToDoubleWithin(Wide v, double lo, double hi) {
  return static_cast<double>(std::clamp(v, Wide{lo}, Wide{hi}));
}

// a + t (b - a) for t in [0, 1]: a point between a and b, never beyond them.
inline double Lerp(double a, double b, Wide t) {
  return ToDoubleWithin(a + t * (Wide{b} - a), std::min(a, b), std::max(a, b));
}

// The point a + t (b - a) of the segment ab, t in [0, 1].
inline Point2 Lerp(const Point2& a, const Point2& b, Wide t) {
  return {Lerp(a.x, b.x, t), Lerp(a.y, b.y, t)};
}

// The midpoint of a and b: halves first, so that nothing overflows; as
// exact as (a + b) / 2 but in the subnormal range.
inline Point2 Midpoint(const Point2& a, const Point2& b) {
  return {a.x * 0.5 + b.x * 0.5, a.y * 0.5 + b.y * 0.5};
}

// (hi - lo) / n, n >= 1: the plain double expression (bit for bit what
// callers computed before) where hi - lo is finite, else in Wide. Infinite
// only when the answer is beyond every double.
inline double Step(double lo, double hi, double n) {
  const double span = hi - lo;
  if (std::isfinite(span)) [[likely]] {
    return span / n;
  }
  return Narrow((Wide{hi} - lo) / n);
}

// lo + k (hi - lo) / n for 0 <= k <= n: the k-th of n equal steps from lo
// towards hi. The plain double expression where it is finite, else in Wide
// (between lo and hi, so finite).
inline double GridLine(double lo, double hi, double k, double n) {
  const double v = lo + k * ((hi - lo) / n);
  if (std::isfinite(v)) [[likely]] {
    return v;
  }
  return Lerp(lo, hi, Wide{k} / n);
}

// a + k b: the plain double expression where it is finite, else in Wide;
// infinite only when the answer is beyond every double.
inline double AddProduct(double a, double k, double b) {
  const double v = a + k * b;
  if (std::isfinite(v)) [[likely]] {
    return v;
  }
  return Narrow(a + Wide{k} * b);
}

// The distance between a and b (up to 2^1025.5, beyond any double).
inline Wide Distance(const Point2& a, const Point2& b) {
  return std::hypot(Wide{b.x} - a.x, Wide{b.y} - a.y);
}

// |a - b|^2, exact to a relative 2^-63 at every scale.
inline Wide SquaredDistanceWide(const Point2& a, const Point2& b) {
  const Wide dx = Wide{b.x} - a.x;
  const Wide dy = Wide{b.y} - a.y;
  return dx * dx + dy * dy;
}

// Sum of weight * value over the terms added, for weights that form a
// convex combination (>= 0 and summing to 1, up to rounding), such as
// barycentric or Sibson coordinates: the exact sum lies between the
// smallest and the largest value added, and so does value(), however near
// +-DBL_MAX the values are (a double sum may overflow there).
class ConvexSum {
 public:
  void Add(double weight, double value) {
    sum_ += Wide{weight} * value;
    lo_ = std::min(lo_, value);
    hi_ = std::max(hi_, value);
  }
  // Precondition: something was added.
  double value() const { return ToDoubleWithin(sum_, lo_, hi_); }

 private:
  Wide sum_ = 0;
  double lo_ = std::numeric_limits<double>::infinity();
  double hi_ = -std::numeric_limits<double>::infinity();
};

}  // namespace locator

#endif  // LOCATOR_CORE_WIDE_MATH_H_
