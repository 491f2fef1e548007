// HilbertKey: the position of a point along a Hilbert curve over a box, to
// order elements so that neighbours in the plane are near in memory.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_HILBERT_H_
#define LOCATOR_CORE_HILBERT_H_

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "common/geometry.h"

namespace locator {

// Position of cell (x, y) of a 2^16 x 2^16 grid along the Hilbert curve.
inline uint32_t HilbertIndex(uint32_t x, uint32_t y) {
  uint32_t d = 0;
  for (uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const uint32_t rx = (x & s) ? 1 : 0;
    const uint32_t ry = (y & s) ? 1 : 0;
    d += s * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant
      if (rx == 1) {
        x = 0xffff - x;
        y = 0xffff - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

// The Hilbert position of p's cell in a 2^16 x 2^16 grid over `box`; points
// outside the box take the nearest border cell. Coordinates are halved
// first, so that no difference overflows for a box or a p anywhere in the
// doubles; halving is exact but in the subnormal range (far below a cell),
// so keys are the same as from the plain differences.
inline uint32_t HilbertKey(const Point2& p, const BoundingBox& box) {
  constexpr double kCells = 65536;
  const auto cell = [](double v, double lo, double hi) {
    const double extent = hi * 0.5 - lo * 0.5;
    const double t = extent > 0 ? (v * 0.5 - lo * 0.5) / extent * kCells : 0;
    return static_cast<uint32_t>(t > 0 ? std::min(t, kCells - 1) : 0);
  };
  return HilbertIndex(cell(p.x, box.min_x, box.max_x),
                      cell(p.y, box.min_y, box.max_y));
}

// The indices of `points` sorted along the Hilbert curve over `box` (ties
// in input order).
inline std::vector<uint32_t> HilbertOrder(std::span<const Point2> points,
                                          const BoundingBox& box) {
  std::vector<std::pair<uint32_t, uint32_t>> keyed(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    keyed[i] = {HilbertKey(points[i], box), static_cast<uint32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> order(points.size());
  for (size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace locator

#endif  // LOCATOR_CORE_HILBERT_H_
