#include "server/core/tiling/hull_edges.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <utility>

#include "server/core/cgal/orientation.h"
#include "server/core/tiling/cells/parallel.h"

namespace locator {

namespace {

bool LexLess(const Point2& a, const Point2& b) {
  return std::tie(a.x, a.y) < std::tie(b.x, b.y);
}

// Andrew's monotone chain over `order` (indices sorted by LexLess), keeping
// points that lie on the boundary between two hull vertices: only strict
// right turns are popped. With `strict`, collinear points are popped too.
std::vector<uint32_t> MonotoneChain(std::span<const Point2> points,
                                    const std::vector<uint32_t>& order,
                                    bool strict) {
  std::vector<uint32_t> ring;
  const auto pops = [&](uint32_t next) {
    const Side turn = Orientation(points[ring[ring.size() - 2]],
                                  points[ring.back()], points[next]);
    return turn == Side::kRight || (strict && turn == Side::kOn);
  };
  const auto chain = [&](auto begin, auto end) {
    const size_t floor = ring.size() + 1;
    for (auto it = begin; it != end; ++it) {
      while (ring.size() > floor && pops(*it)) ring.pop_back();
      ring.push_back(*it);
    }
    ring.pop_back();  // the next chain starts there
  };
  // The lower chain left to right, then the upper chain right to left.
  chain(order.begin(), order.end());
  chain(order.rbegin(), order.rend());
  return ring;
}

// The vertices of the convex polygon of the extreme points in 8 directions
// (the axes and diagonals), counter-clockwise. Diagonal extremes are found
// in rounded arithmetic; any data points will do, as their hull is taken
// exactly.
std::vector<Point2> ExtremePolygon(std::span<const Point2> points) {
  std::array<uint32_t, 8> best{};
  const auto score = [](const Point2& p, int d) {
    switch (d) {
      case 0:
        return p.x;
      case 1:
        return p.y;
      case 2:
        return p.x + p.y;
      default:
        return p.x - p.y;
    }
  };
  for (uint32_t i = 1; i < points.size(); ++i) {
    for (int d = 0; d < 4; ++d) {
      if (score(points[i], d) < score(points[best[2 * d]], d)) best[2 * d] = i;
      if (score(points[i], d) > score(points[best[2 * d + 1]], d)) {
        best[2 * d + 1] = i;
      }
    }
  }
  std::vector<uint32_t> order(best.begin(), best.end());
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return LexLess(points[a], points[b]);
  });
  order.erase(std::unique(order.begin(), order.end(),
                          [&](uint32_t a, uint32_t b) {
                            return !LexLess(points[a], points[b]);
                          }),
              order.end());
  std::vector<Point2> polygon;
  if (order.size() < 3) return polygon;
  for (const uint32_t i : MonotoneChain(points, order, /*strict=*/true)) {
    polygon.push_back(points[i]);
  }
  if (polygon.size() < 3) polygon.clear();  // all extremes collinear
  return polygon;
}

}  // namespace

HullEdges HullEdges::Compute(std::span<const Point2> points, unsigned threads) {
  // Points strictly inside a convex polygon of data points are strictly
  // inside the hull: drop them (most points, for most data).
  const std::vector<Point2> polygon = ExtremePolygon(points);
  const auto inside = [&](const Point2& p) {
    if (polygon.empty()) return false;
    for (size_t k = 0; k < polygon.size(); ++k) {
      if (Orientation(polygon[k], polygon[(k + 1) % polygon.size()], p) !=
          Side::kLeft) {
        return false;
      }
    }
    return true;
  };
  std::vector<std::vector<uint32_t>> kept(std::max(threads, 1u));
  ParallelSlices(points.size(), threads,
                 [&](size_t begin, size_t end, size_t slice) {
                   for (size_t i = begin; i < end; ++i) {
                     if (!inside(points[i])) {
                       kept[slice].push_back(static_cast<uint32_t>(i));
                     }
                   }
                 });
  std::vector<uint32_t> order;
  for (const auto& part : kept)
    order.insert(order.end(), part.begin(), part.end());
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return LexLess(points[a], points[b]);
  });

  return FromRing(MonotoneChain(points, order, /*strict=*/false));
}

HullEdges HullEdges::FromRing(std::vector<uint32_t> ring) {
  HullEdges hull;
  hull.ring_ = std::move(ring);
  const size_t h = hull.ring_.size();
  for (size_t k = 0; k < h; ++k) {
    const auto [a, b] = std::minmax(hull.ring_[k], hull.ring_[(k + 1) % h]);
    hull.edges_.push_back(uint64_t{a} << 32 | b);
  }
  std::sort(hull.edges_.begin(), hull.edges_.end());
  return hull;
}

HullEdges HullEdges::Renumbered(std::span<const uint32_t> index) const {
  std::vector<uint32_t> ring;
  ring.reserve(ring_.size());
  for (const uint32_t i : ring_) ring.push_back(index[i]);
  return FromRing(std::move(ring));
}

bool HullEdges::Contains(uint32_t a, uint32_t b) const {
  const auto [lo, hi] = std::minmax(a, b);
  return std::binary_search(edges_.begin(), edges_.end(),
                            uint64_t{lo} << 32 | hi);
}

}  // namespace locator
