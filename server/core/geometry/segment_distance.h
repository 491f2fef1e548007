// SegmentDistance2: the squared distance from a point to a segment, shared by
// the nearest hull edge and the nearest domain boundary edge searches.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_SEGMENT_DISTANCE_H_
#define LOCATOR_CORE_SEGMENT_DISTANCE_H_

#include "locator/geometry.h"

namespace locator {

// Squared distance from q to segment ab, in long double so that coordinates
// near 1e308 do not overflow. An endpoint is measured directly (not as a
// clamped projection), so two edges that are nearest at their shared vertex
// tie exactly.
inline long double SegmentDistance2(const Point2& a, const Point2& b,
                                    const Point2& q) {
  using Real = long double;
  const auto d2 = [&q](const Point2& p) {
    const Real dx = Real{q.x} - p.x;
    const Real dy = Real{q.y} - p.y;
    return dx * dx + dy * dy;
  };
  const Real abx = Real{b.x} - a.x;
  const Real aby = Real{b.y} - a.y;
  const Real aqx = Real{q.x} - a.x;
  const Real aqy = Real{q.y} - a.y;
  const Real dot = aqx * abx + aqy * aby;
  const Real len2 = abx * abx + aby * aby;
  if (dot <= 0) return d2(a);
  if (dot >= len2) return d2(b);
  const Real cross = aqx * aby - aqy * abx;
  return cross * cross / len2;
}

}  // namespace locator

#endif  // LOCATOR_CORE_SEGMENT_DISTANCE_H_
