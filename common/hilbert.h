// HilbertKey: the position of a point along a Hilbert curve over a box, to
// order elements so that neighbours in the plane are near in memory.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_COMMON_HILBERT_H_
#define LOCATOR_COMMON_HILBERT_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "locator/geometry.h"

namespace locator {

namespace hilbert_internal {

// The Hilbert walk four levels at a time. From the largest quadrants down,
// a quadrant's bits, seen in the frame the quadrants above it left (x and y
// exchanged or not, both complemented or not: two bits of state, as the
// two commute), give two bits of the position, and the lower left and
// right quadrants turn the frame. Entry (state << 8 | 4 bits of x << 4 |
// 4 bits of y) holds the 8 position bits of those four levels and, above
// them, the state after them: four table look-ups per key, no branches to
// mispredict (builds and batches compute millions of keys).
constexpr std::array<uint16_t, 1024> MakeWalkTable() {
  std::array<uint16_t, 1024> table{};
  for (uint32_t state = 0; state < 4; ++state) {
    for (uint32_t xs = 0; xs < 16; ++xs) {
      for (uint32_t ys = 0; ys < 16; ++ys) {
        uint32_t swap = state & 1;
        uint32_t complement = state >> 1;
        uint32_t d = 0;
        for (int level = 3; level >= 0; --level) {
          const uint32_t bx = ((xs >> level) & 1) ^ complement;
          const uint32_t by = ((ys >> level) & 1) ^ complement;
          const uint32_t rx = swap ? by : bx;
          const uint32_t ry = swap ? bx : by;
          d = (d << 2) | ((3 * rx) ^ ry);
          if (ry == 0) {
            complement ^= rx;
            swap ^= 1;
          }
        }
        table[state << 8 | xs << 4 | ys] =
            static_cast<uint16_t>(d | (swap | complement << 1) << 8);
      }
    }
  }
  return table;
}

inline constexpr std::array<uint16_t, 1024> kWalkTable = MakeWalkTable();

}  // namespace hilbert_internal

// Position of cell (x, y) of a 2^16 x 2^16 grid along the Hilbert curve.
inline uint32_t HilbertIndex(uint32_t x, uint32_t y) {
  uint32_t d = 0;
  uint32_t state = 0;
  for (int shift = 12; shift >= 0; shift -= 4) {
    const uint32_t step =
        hilbert_internal::kWalkTable[state << 8 | ((x >> shift) & 15) << 4 |
                                     ((y >> shift) & 15)];
    d = d << 8 | (step & 0xff);
    state = step >> 8;
  }
  return d;
}

// The cell of coordinate v in a 2^16 grid over [lo, hi]; values outside
// take the nearest border cell. Monotone in v, also where hi - lo
// overflows a double (then computed on halves, which cannot).
inline uint32_t HilbertCell(double v, double lo, double hi) {
  constexpr double kCells = 65536;
  const double extent = hi - lo;
  double t = 0;
  if (std::isfinite(extent)) {
    if (extent > 0) t = (v - lo) / extent * kCells;
  } else {
    t = (v * 0.5 - lo * 0.5) / (hi * 0.5 - lo * 0.5) * kCells;
  }
  if (!(t > 0)) return 0;  // also NaN
  return t >= kCells - 1 ? 0xffffu : static_cast<uint32_t>(t);
}

// The Hilbert position of p's cell in a 2^16 x 2^16 grid over `box`; points
// outside the box take the nearest border cell; defined for a box and a p
// anywhere in the doubles (HilbertCell).
inline uint32_t HilbertKey(const Point2& p, const BoundingBox& box) {
  return HilbertIndex(HilbertCell(p.x, box.min_x, box.max_x),
                      HilbertCell(p.y, box.min_y, box.max_y));
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

#endif  // LOCATOR_COMMON_HILBERT_H_
