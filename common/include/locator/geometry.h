// Plain geometry value types shared by the core and its callers.
//
// These are deliberately not CGAL types: app code (service, clients, bench
// drivers) stays free of CGAL templates. The triangulation adapter converts.

#ifndef LOCATOR_GEOMETRY_H_
#define LOCATOR_GEOMETRY_H_

#include <algorithm>
#include <cmath>
#include <limits>

namespace locator {

struct Point2 {
  double x = 0;
  double y = 0;
};

inline bool IsFinite(const Point2& p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

inline double SquaredDistance(const Point2& a, const Point2& b) {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return dx * dx + dy * dy;
}

// Axis-aligned rectangle [min_x, max_x] x [min_y, max_y]. A default-constructed
// box is empty (min > max) and grows with Extend().
struct BoundingBox {
  double min_x = std::numeric_limits<double>::infinity();
  double min_y = std::numeric_limits<double>::infinity();
  double max_x = -std::numeric_limits<double>::infinity();
  double max_y = -std::numeric_limits<double>::infinity();

  bool empty() const { return min_x > max_x || min_y > max_y; }
  double width() const { return max_x - min_x; }
  double height() const { return max_y - min_y; }
  void Extend(const Point2& p) {
    min_x = std::min(min_x, p.x);
    min_y = std::min(min_y, p.y);
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
  }
  bool Contains(const Point2& p) const {
    return p.x >= min_x && p.x <= max_x && p.y >= min_y && p.y <= max_y;
  }
  // The box grown by `fraction` of its width/height on every side.
  BoundingBox Inflated(double fraction) const {
    const double dx = width() * fraction;
    const double dy = height() * fraction;
    return BoundingBox{min_x - dx, min_y - dy, max_x + dx, max_y + dy};
  }
};

}  // namespace locator

#endif  // LOCATOR_GEOMETRY_H_
