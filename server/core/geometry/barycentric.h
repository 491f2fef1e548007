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
#include "server/core/cgal/orientation.h"

namespace locator {

// Barycentric coordinates of q in the non-degenerate triangle (a, b, c):
// q = result[0] a + result[1] b + result[2] c, and they sum to 1 (up to
// rounding). q may lie outside the triangle (then some are negative).
// Precondition: all four points finite (an infinity or NaN would reach
// GMP, which raises SIGFPE on it).
std::array<double, 3> Barycentric(const Point2& a, const Point2& b,
                                  const Point2& c, const Point2& q);

// Barycentric() for the many points of a scan that fall in one triangle:
// the triangle's own cross product is computed once, and a point's two
// come from the orientation filters that placed it there.
//
// Thread-safety: immutable after construction.
class TriangleBarycentric {
 public:
  // Precondition: (a, b, c) is non-degenerate and finite.
  TriangleBarycentric(const Point2& a, const Point2& b, const Point2& c);

  // Barycentric(a, b, c, q), bit for bit, given OrientationFilter(b, c, q)
  // and OrientationFilter(c, a, q): their determinants are the cross
  // products Barycentric() computes in double, so where that resolves q
  // nothing is computed again; elsewhere it calls Barycentric().
  // Precondition: IsFinite(q).
  std::array<double, 3> Of(const Point2& q, const OrientationFilter& bcq,
                           const OrientationFilter& caq) const;

 private:
  Point2 a_, b_, c_;
  double area_ = 0;        // the cross product (b - a) x (c - a)
  double magnitude_ = 0;   // the magnitudes of its terms, summed
  bool resolves_ = false;  // whether double resolves the area
};

// Barycentric coordinates of q on edge `edge` (opposite that corner) of the
// triangle `corners`: 0 for the opposite corner, the other two renormalised
// to sum to 1.
std::array<double, 3> EdgeBarycentric(const std::array<Point2, 3>& corners,
                                      int edge, const Point2& q);

}  // namespace locator

#endif  // LOCATOR_CORE_BARYCENTRIC_H_
