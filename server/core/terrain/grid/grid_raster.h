// The samples a triangle of grid points covers, row by row, found with
// exact integer edge functions: each row's run of samples is computed from
// the edges (no per-sample inside test), so a sample on an edge is in it
// exactly when it lies on that edge.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_TERRAIN_GRID_RASTER_H_
#define LOCATOR_CORE_TERRAIN_GRID_RASTER_H_

#include <algorithm>
#include <array>
#include <cstdint>

#include "server/core/terrain/grid/grid_domain.h"

namespace locator {

namespace grid_raster_internal {

// floor(n / d) for d > 0.
inline int64_t FloorDiv(int64_t n, int64_t d) {
  return n >= 0 ? n / d : -((-n + d - 1) / d);
}

// floor(n(y) / d) for n(y) = n + step * (y - y0), row after row from y0,
// with one division up front and none per row.
class FloorSteps {
 public:
  FloorSteps() = default;
  FloorSteps(int64_t n, int64_t step, int64_t d)
      : q_(FloorDiv(n, d)),
        r_(n - q_ * d),
        dq_(FloorDiv(step, d)),
        dr_(step - dq_ * d),
        d_(d) {}
  int64_t value() const { return q_; }
  void Next() {
    q_ += dq_;
    r_ += dr_;
    if (r_ >= d_) {
      r_ -= d_;
      ++q_;
    }
  }

 private:
  int64_t q_ = 0, r_ = 0;    // n = q * d + r, 0 <= r < d
  int64_t dq_ = 0, dr_ = 0;  // step = dq * d + dr, 0 <= dr < d
  int64_t d_ = 1;
};

}  // namespace grid_raster_internal

// The edge function of the edge from p to q: positive left of it (inside a
// counter-clockwise triangle), 0 on its line. As a function of x in row y
// it is a * x + k(y), with a = p.y - q.y and k(y) = b * (y - p.y) - a * p.x.
struct EdgeFunction {
  int64_t a, b, k0;  // k(y) = b * y + k0
  EdgeFunction(const GridPoint& p, const GridPoint& q)
      : a(p.y - q.y), b(q.x - p.x), k0(-b * p.y - a * p.x) {}
  int64_t At(int64_t x, int64_t y) const { return a * x + b * y + k0; }
};

// Triangles whose bounding box holds at most this many samples are
// scanned sample by sample, without the divisions of the row bounds.
inline constexpr int64_t kSmallBox = 64;

// Calls visit(row, first, last) for each row holding samples of the
// counter-clockwise triangle `c`, with first <= last the columns of its
// run. The closed triangle's samples, but those on edge i (from corner i
// to corner i + 1) when open[i], and the corners when skip_corners.
template <class Visit>
void ForEachRun(const std::array<GridPoint, 3>& c, std::array<bool, 3> open,
                bool skip_corners, Visit&& visit) {
  using grid_raster_internal::FloorSteps;
  const int64_t x_min = std::min({c[0].x, c[1].x, c[2].x});
  const int64_t x_max = std::max({c[0].x, c[1].x, c[2].x});
  const int64_t y_min = std::min({c[0].y, c[1].y, c[2].y});
  const int64_t y_max = std::max({c[0].y, c[1].y, c[2].y});
  const auto trim_corners = [&](int64_t y, int64_t* first, int64_t* last) {
    // A corner is an extreme point: it ends its row's run.
    for (const GridPoint& corner : c) {
      if (corner.y != y) continue;
      if (corner.x == *first) {
        ++*first;
      } else if (corner.x == *last) {
        --*last;
      }
    }
  };
  if ((x_max - x_min + 1) * (y_max - y_min + 1) <= kSmallBox) {
    // A small triangle: test each sample of its box, no division.
    const std::array<EdgeFunction, 3> edges = {EdgeFunction(c[0], c[1]),
                                               EdgeFunction(c[1], c[2]),
                                               EdgeFunction(c[2], c[0])};
    for (int64_t y = y_min; y <= y_max; ++y) {
      int64_t first = x_max + 1;
      int64_t last = x_min - 1;
      for (int64_t x = x_min; x <= x_max; ++x) {
        bool inside = true;
        for (int i = 0; i < 3; ++i) {
          const int64_t w = edges[i].At(x, y);
          inside &= open[i] ? w > 0 : w >= 0;
        }
        if (!inside) continue;
        first = std::min(first, x);
        last = x;
      }
      if (skip_corners) trim_corners(y, &first, &last);
      if (first <= last) visit(y, first, last);
    }
    return;
  }
  // Inside edge i: a x + k(y) >= 0 (> 0 when open). With a > 0 that bounds
  // the run's first column, with a < 0 its last, with a = 0 the whole row.
  enum class Kind { kFirst, kLast, kRow };
  struct Bound {
    Kind kind;
    int64_t offset;    // kFirst: first >= offset - q; kLast: last <= q + offset
    FloorSteps steps;  // q
    int64_t k, b;      // kRow: k(y), stepping by b
    bool open;
  };
  std::array<Bound, 3> bounds;
  for (int i = 0; i < 3; ++i) {
    const EdgeFunction edge(c[i], c[(i + 1) % 3]);
    Bound& bound = bounds[i];
    bound.open = open[i];
    bound.b = edge.b;
    bound.k = edge.b * y_min + edge.k0;
    if (edge.a > 0) {
      // x >= -floor(k / a), or x >= 1 - floor((k + a - 1) / a) when open.
      bound.kind = Kind::kFirst;
      bound.offset = open[i] ? 1 : 0;
      bound.steps =
          FloorSteps(bound.k + (open[i] ? edge.a - 1 : 0), edge.b, edge.a);
    } else if (edge.a < 0) {
      // x <= floor(k / d), or x <= floor((k + d - 1) / d) - 1 when open.
      const int64_t d = -edge.a;
      bound.kind = Kind::kLast;
      bound.offset = open[i] ? -1 : 0;
      bound.steps = FloorSteps(bound.k + (open[i] ? d - 1 : 0), edge.b, d);
    } else {
      bound.kind = Kind::kRow;
    }
  }
  for (int64_t y = y_min; y <= y_max; ++y) {
    int64_t first = x_min;
    int64_t last = x_max;
    for (Bound& bound : bounds) {
      switch (bound.kind) {
        case Kind::kFirst:
          first = std::max(first, bound.offset - bound.steps.value());
          bound.steps.Next();
          break;
        case Kind::kLast:
          last = std::min(last, bound.steps.value() + bound.offset);
          bound.steps.Next();
          break;
        case Kind::kRow:
          if (bound.open ? bound.k <= 0 : bound.k < 0) first = last + 1;
          bound.k += bound.b;
          break;
      }
    }
    if (skip_corners) trim_corners(y, &first, &last);
    if (first <= last) visit(y, first, last);
  }
}

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_GRID_RASTER_H_
