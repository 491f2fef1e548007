// Circles through three points: CGAL's exact in-circle predicate
// (side_of_oriented_circle) on plain points, like orientation.h. The
// kernel's types stay in this header.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_CIRCLE_H_
#define LOCATOR_CORE_CIRCLE_H_

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "locator/geometry.h"

namespace locator {

namespace circle_internal {
using CgalPoint = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
inline CgalPoint ToCgal(const Point2& p) { return CgalPoint(p.x, p.y); }
}  // namespace circle_internal

// Whether q lies strictly inside the circle through the counter-clockwise
// triangle a, b, c. Exact.
inline bool InsideCircumcircle(const Point2& a, const Point2& b,
                               const Point2& c, const Point2& q) {
  using circle_internal::ToCgal;
  return CGAL::side_of_oriented_circle(ToCgal(a), ToCgal(b), ToCgal(c),
                                       ToCgal(q)) == CGAL::ON_POSITIVE_SIDE;
}

}  // namespace locator

#endif  // LOCATOR_CORE_CIRCLE_H_
