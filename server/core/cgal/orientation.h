// Orientation: CGAL's exact orientation predicate on plain points.
//
// The serving mesh stores doubles; every side test still goes through CGAL's
// filtered exact predicate (Exact_predicates_inexact_constructions_kernel),
// so answers on edges and vertices are exact and identical to CGAL's own.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_ORIENTATION_H_
#define LOCATOR_CORE_ORIENTATION_H_

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <limits>

#include "locator/geometry.h"

namespace locator {

// Which side of the directed line a -> b the point c lies on.
enum class Side : int8_t { kRight = -1, kOn = 0, kLeft = 1 };

// The filter in plain double (Shewchuk's orient2d fast path, with a wider
// bound): it decides whenever the determinant is clear of its rounding
// error, which it bounds relative to |left| + |right| as long as no product
// under- or overflows (hence the range check).
struct OrientationFilter {
  static constexpr double kErrorBound = 8 * 0x1p-53;
  static constexpr double kMinTerms = 0x1p-900;
  static constexpr double kMaxTerms = 0x1p1000;

  // The determinant of (a, b, c) and the bound on its rounding error; a
  // bound of NaN when the terms are out of range (no sign is then decided).
  // The determinant is the cross product (a - c) x (b - c), computed as
  // Barycentric() computes its cross products (TriangleBarycentric).
  OrientationFilter(const Point2& a, const Point2& b, const Point2& c) {
    const double left = (a.x - c.x) * (b.y - c.y);
    const double right = (a.y - c.y) * (b.x - c.x);
    determinant = left - right;
    terms = std::abs(left) + std::abs(right);
    bound = terms >= kMinTerms && terms <= kMaxTerms
                ? kErrorBound * terms
                : std::numeric_limits<double>::quiet_NaN();
  }
  // True only when Orientation(a, b, c) is kLeft (kRight).
  bool ClearlyLeft() const { return determinant > bound; }
  bool ClearlyRight() const { return determinant < -bound; }

  double determinant;
  double terms;  // |left| + |right|: the scale of the rounding error
  double bound;
};

// The filter first; what it leaves undecided goes to CGAL's filtered exact
// predicate.
inline Side Orientation(const Point2& a, const Point2& b, const Point2& c) {
  const OrientationFilter filter(a, b, c);
  if (filter.ClearlyLeft()) return Side::kLeft;
  if (filter.ClearlyRight()) return Side::kRight;
  using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  return static_cast<Side>(static_cast<int>(
      CGAL::orientation(P(a.x, a.y), P(b.x, b.y), P(c.x, c.y))));
}

}  // namespace locator

#endif  // LOCATOR_CORE_ORIENTATION_H_
