// SegmentCrossing: where two crossing segments cross, rounded, at any
// scale and for any ratio of their lengths: a profile's 1e160-long line
// crossing a unit triangle's edge, or a short line crossing an edge that
// spans the doubles.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_SEGMENT_CROSSING_H_
#define LOCATOR_CORE_SEGMENT_CROSSING_H_

#include "locator/geometry.h"

namespace locator {

// The point where segment pq crosses segment ab, within 2^-50 of the
// shorter one's length of the exact crossing, and inside both segments'
// boxes (as the exact one is). Interpolated in long double along the
// shorter segment, where the fraction's rounding moves it least, or from
// exact rationals where the cross products' rounding is too large against
// them (one segment 2^14 times longer than the other's distance from the
// crossing, and more). Precondition: all four points finite, a and b on
// opposite sides of (or one on) the line pq, p and q likewise for ab, and
// not all four collinear.
Point2 SegmentCrossing(const Point2& p, const Point2& q, const Point2& a,
                       const Point2& b);

}  // namespace locator

#endif  // LOCATOR_CORE_SEGMENT_CROSSING_H_
