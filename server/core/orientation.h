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

#include "common/geometry.h"

namespace locator {

// Which side of the directed line a -> b the point c lies on.
enum class Side : int8_t { kRight = -1, kOn = 0, kLeft = 1 };

inline Side Orientation(const Point2& a, const Point2& b, const Point2& c) {
  using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  return static_cast<Side>(static_cast<int>(
      CGAL::orientation(P(a.x, a.y), P(b.x, b.y), P(c.x, c.y))));
}

}  // namespace locator

#endif  // LOCATOR_CORE_ORIENTATION_H_
