// Barycentric coordinates of a point in a triangle, to within 2^-40 over
// the whole double range and for needles of any thinness: double
// arithmetic where its rounding provably stays within that, long double
// beyond, and exact rationals where long double cannot resolve them.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_BARYCENTRIC_H_
#define LOCATOR_CORE_BARYCENTRIC_H_

#include <array>

#include "locator/geometry.h"

namespace locator {

// Barycentric coordinates of q in the non-degenerate triangle (a, b, c):
// q = result[0] a + result[1] b + result[2] c, and they sum to 1 (up to
// rounding). q may lie outside the triangle (then some are negative).
// Precondition: all four points finite (an infinity or NaN would reach
// GMP, which raises SIGFPE on it).
std::array<double, 3> Barycentric(const Point2& a, const Point2& b,
                                  const Point2& c, const Point2& q);

// Barycentric coordinates of q on edge `edge` (opposite that corner) of the
// triangle `corners`: 0 for the opposite corner, the other two renormalised
// to sum to 1.
std::array<double, 3> EdgeBarycentric(const std::array<Point2, 3>& corners,
                                      int edge, const Point2& q);

}  // namespace locator

#endif  // LOCATOR_CORE_BARYCENTRIC_H_
